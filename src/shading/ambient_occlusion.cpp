#include "softraster/shading/ambient_occlusion.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "softraster/srgb.h"
#include "softraster/worker_pool.h"

namespace softraster {

const std::array<glm::vec2, kAmbientOcclusionSamples>& ambient_occlusion_kernel() {
    static const std::array<glm::vec2, kAmbientOcclusionSamples> kernel = [] {
        std::array<glm::vec2, kAmbientOcclusionSamples> k{};
        const double golden = M_PI * (3.0 - std::sqrt(5.0));
        for (int i = 0; i < kAmbientOcclusionSamples; ++i) {
            const double r = std::sqrt((i + 0.5) / kAmbientOcclusionSamples), a = i * golden;
            k[size_t(i)] = glm::vec2(float(r * std::cos(a)), float(r * std::sin(a)));
        }
        return k;
    }();
    return kernel;
}

namespace {

// The view-space position of pixel (x, y) at window depth d: the inverse projection of its
// NDC point (x right, y up, z from the depth range [0, 1]), divided by w. Written out term
// by term in this order (the reference's GLSL does the same).
glm::vec3 view_position(const glm::mat4& inv, int x, int y, float d, int width, int height) {
    const float nx = 2.0f * (float(x) + 0.5f) / float(width) - 1.0f;
    const float ny = 1.0f - 2.0f * (float(y) + 0.5f) / float(height);
    const float nz = 2.0f * d - 1.0f;
    float c[4];
    for (int j = 0; j < 4; ++j) c[j] = inv[0][j] * nx + inv[1][j] * ny + inv[2][j] * nz + inv[3][j];
    return glm::vec3(c[0] / c[3], c[1] / c[3], c[2] / c[3]);
}

}  // namespace

std::vector<float> ambient_occlusion(const float* depth, int width, int height, const glm::mat4& projection,
                                     const AmbientOcclusionSettings& s, WorkerPool* pool) {
    const size_t pixels = size_t(width) * size_t(height);
    const glm::mat4 inv = glm::mat4(glm::inverse(glm::dmat4(projection)));
    // Every pixel's position once; the samples only look them up.
    std::vector<glm::vec3> position(pixels);
    std::vector<float> ao(pixels, 1.0f);
    auto rows = [&](auto&& row) { parallel_for(pool, size_t(height), [&](size_t y, unsigned) { row(int(y)); }); };
    rows([&](int y) {
        for (int x = 0; x < width; ++x) {
            const size_t i = size_t(y) * size_t(width) + size_t(x);
            position[i] = view_position(inv, x, y, depth[i], width, height);
        }
    });
    const auto& kernel = ambient_occlusion_kernel();
    const float r2 = s.radius * s.radius;
    // Pixels per scene unit at a view-space point: the projection's vertical scale over
    // the clip-space w there, times half the height.
    auto pixels_per_unit = [&](const glm::vec3& p) {
        const float w = projection[0][3] * p.x + projection[1][3] * p.y + projection[2][3] * p.z + projection[3][3];
        return projection[1][1] * float(height) * 0.5f / w;
    };
    rows([&](int y) {
        for (int x = 0; x < width; ++x) {
            const size_t i = size_t(y) * size_t(width) + size_t(x);
            if (!(depth[i] < 1.0f)) continue;
            const glm::vec3 p = position[i];
            // The tangents: toward the neighbour whose depth is closer (so an edge takes the
            // surface the pixel is on, not the one behind it), one-sided at the border.
            auto tangent = [&](bool has_before, bool has_after, size_t before, size_t after) {
                if (!has_after) return has_before ? p - position[before] : glm::vec3(0.0f);
                const glm::vec3 a = position[after] - p;
                if (!has_before) return a;
                const glm::vec3 b = p - position[before];
                return std::abs(a.z) < std::abs(b.z) ? a : b;
            };
            const glm::vec3 tx = tangent(x > 0, x + 1 < width, i - 1, i + 1);
            const glm::vec3 ty = tangent(y > 0, y + 1 < height, i - size_t(width), i + size_t(width));
            glm::vec3 n = glm::cross(tx, ty);
            const float len = std::sqrt(glm::dot(n, n));
            if (!(len > 0.0f)) continue;
            n = n / len;
            if (glm::dot(n, p) > 0.0f) n = -n;  // toward the camera, at the origin
            const float scale = s.radius * pixels_per_unit(p);
            float sum = 0.0f;
            for (const glm::vec2& k : kernel) {
                const float fx = std::floor(float(x) + 0.5f + scale * k.x), fy = std::floor(float(y) + 0.5f + scale * k.y);
                if (!(fx >= 0.0f && fx < float(width) && fy >= 0.0f && fy < float(height))) continue;
                const int qx = int(fx), qy = int(fy);
                if (qx == x && qy == y) continue;
                const glm::vec3 v = position[size_t(qy) * size_t(width) + size_t(qx)] - p;
                const float vv = glm::dot(v, v);
                if (!(vv > 0.0f)) continue;
                const float rise = glm::dot(n, v) / std::sqrt(vv) - s.bias;
                const float fade = 1.0f - vv / r2;
                if (rise > 0.0f && fade > 0.0f) sum += rise * fade;
            }
            ao[i] = std::clamp(1.0f - s.intensity / float(kAmbientOcclusionSamples) * sum, 0.0f, 1.0f);
        }
    });
    return ao;
}

void apply_ambient_occlusion(Image& picture, const std::vector<float>& ao, ColorSpace color) {
    for (size_t i = 0; i < picture.pixels.size(); ++i) {
        Rgba8& c = picture.pixels[i];
        const float f = ao[i];
        if (f == 1.0f) continue;
        for (uint8_t* v : {&c.r, &c.g, &c.b}) {
            if (color == ColorSpace::Srgb) *v = srgb::encode(srgb::decode(*v) * f);
            else *v = uint8_t(std::floor(float(*v) * f + 0.5f));
        }
    }
}

}  // namespace softraster

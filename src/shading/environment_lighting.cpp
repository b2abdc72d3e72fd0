// The environment's maps (environment_lighting.h), computed once per scene in double
// precision, stored as float.
#include "softraster/shading/environment_lighting.h"

#include <cmath>
#include <cstdint>
#include <string>

#include <ImfArray.h>
#include <ImfRgbaFile.h>
#include <sleef.h>
#include <stb_image.h>

#include "io/read_file.h"
#include "softraster/error.h"

namespace softraster {
namespace {

constexpr double kPi = 3.14159265358979323846;

glm::dvec3 texel_direction(int i, int j, int w, int h) {
    const double p = 2.0 * kPi * ((i + 0.5) / w - 0.5), t = kPi * (j + 0.5) / h;
    return {std::sin(t) * std::sin(p), std::cos(t), -std::sin(t) * std::cos(p)};
}

// Level 0 of the specular maps: each texel the mean of the picture's texels whose centers
// fall in it; for a smaller picture, the picture's texel under its center.
EquirectImage base_level(const EquirectImage& src) {
    const int w = EnvironmentLighting::kBaseWidth, h = EnvironmentLighting::kBaseHeight;
    EquirectImage out{w, h, std::vector<glm::vec3>(size_t(w) * size_t(h))};
    if (src.width >= w && src.height >= h) {
        std::vector<glm::dvec3> sum(out.texels.size(), glm::dvec3(0.0));
        std::vector<int> count(out.texels.size(), 0);
        for (int j = 0; j < src.height; ++j)
            for (int i = 0; i < src.width; ++i) {
                const size_t k = size_t(int64_t(j) * h / src.height) * size_t(w) + size_t(int64_t(i) * w / src.width);
                sum[k] += glm::dvec3(src.at(i, j));
                ++count[k];
            }
        for (size_t k = 0; k < sum.size(); ++k) out.texels[k] = glm::vec3(sum[k] / double(count[k]));
    } else {
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i)
                out.texels[size_t(j) * size_t(w) + size_t(i)] = src.at(int(int64_t(i) * src.width / w), int(int64_t(j) * src.height / h));
    }
    return out;
}

// Half the size: the mean of each 2 x 2.
EquirectImage half(const EquirectImage& m) {
    EquirectImage out{m.width / 2, m.height / 2, {}};
    out.texels.resize(size_t(out.width) * size_t(out.height));
    for (int j = 0; j < out.height; ++j)
        for (int i = 0; i < out.width; ++i)
            out.texels[size_t(j) * size_t(out.width) + size_t(i)] =
                glm::vec3((glm::dvec3(m.at(2 * i, 2 * j)) + glm::dvec3(m.at(2 * i + 1, 2 * j)) + glm::dvec3(m.at(2 * i, 2 * j + 1)) +
                           glm::dvec3(m.at(2 * i + 1, 2 * j + 1))) / 4.0);
    return out;
}

// The i-th of n points of the Hammersley set: (i / n, the bits of i mirrored).
glm::dvec2 hammersley(uint32_t i, uint32_t n) {
    uint32_t b = i;
    b = (b << 16u) | (b >> 16u);
    b = ((b & 0x55555555u) << 1u) | ((b & 0xAAAAAAAAu) >> 1u);
    b = ((b & 0x33333333u) << 2u) | ((b & 0xCCCCCCCCu) >> 2u);
    b = ((b & 0x0F0F0F0Fu) << 4u) | ((b & 0xF0F0F0F0u) >> 4u);
    b = ((b & 0x00FF00FFu) << 8u) | ((b & 0xFF00FF00u) >> 8u);
    return {double(i) / double(n), double(b) * 2.3283064365386963e-10};
}

// A GGX-distributed half vector around n for the point xi (a2 = alpha^2).
glm::dvec3 ggx_half_vector(const glm::dvec2& xi, double a2, const glm::dvec3& n) {
    const double phi = 2.0 * kPi * xi.x;
    const double cos_t = std::sqrt((1.0 - xi.y) / (1.0 + (a2 - 1.0) * xi.y)), sin_t = std::sqrt(1.0 - cos_t * cos_t);
    const glm::dvec3 up = std::abs(n.z) < 0.999 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    const glm::dvec3 t = glm::normalize(glm::cross(up, n)), b = glm::cross(n, t);
    return glm::normalize(t * (sin_t * std::cos(phi)) + b * (sin_t * std::sin(phi)) + n * cos_t);
}

// Trilinear lookup in a box pyramid (for the prefilter's samples).
glm::dvec3 sample_pyramid(const std::vector<EquirectImage>& pyramid, const glm::dvec3& d, double lod) {
    lod = std::clamp(lod, 0.0, double(pyramid.size() - 1));
    const int l0 = int(lod);
    const double f = lod - l0;
    const glm::vec2 uv = equirect_uv(glm::vec3(d));
    const glm::dvec3 a(sample_bilinear(pyramid[size_t(l0)], uv));
    if (l0 + 1 >= int(pyramid.size())) return a;
    return a * (1.0 - f) + glm::dvec3(sample_bilinear(pyramid[size_t(l0 + 1)], uv)) * f;
}

// Level k: for each texel's direction N (= V = R), the mean of the environment over a GGX
// lobe of roughness k / 5 weighted by N.L, from 64 samples, each read from the pyramid level
// whose texels match the sample's share of the lobe (Colbert and Krivanek 2007, "GPU-based
// importance sampling", with Karis's +1).
EquirectImage prefilter(const std::vector<EquirectImage>& pyramid, int level) {
    constexpr uint32_t kSamples = 64;
    const double roughness = double(level) / (EnvironmentLighting::kLevels - 1), alpha = roughness * roughness, a2 = alpha * alpha;
    const EquirectImage& size = pyramid[size_t(level)];
    EquirectImage out{size.width, size.height, std::vector<glm::vec3>(size.texels.size())};
    const double texel_solid_angle = 4.0 * kPi / (double(pyramid[0].width) * double(pyramid[0].height));
    for (int j = 0; j < out.height; ++j)
        for (int i = 0; i < out.width; ++i) {
            const glm::dvec3 n = texel_direction(i, j, out.width, out.height);
            glm::dvec3 sum(0.0);
            double weight = 0.0;
            for (uint32_t s = 0; s < kSamples; ++s) {
                const glm::dvec3 h = ggx_half_vector(hammersley(s, kSamples), a2, n);
                const double nh = glm::dot(n, h);
                const glm::dvec3 l = 2.0 * nh * h - n;
                const double nl = glm::dot(n, l);
                if (!(nl > 0.0)) continue;
                const double dd = nh * nh * (a2 - 1.0) + 1.0, d = a2 / (kPi * dd * dd);
                const double pdf = d / 4.0;  // D (N.H) / (4 V.H), N = V
                const double lod = 0.5 * std::log2(1.0 / (kSamples * pdf) / texel_solid_angle) + 1.0;
                sum += sample_pyramid(pyramid, l, lod) * nl;
                weight += nl;
            }
            out.texels[size_t(j) * size_t(out.width) + size_t(i)] = glm::vec3(weight > 0.0 ? sum / weight : sum);
        }
    return out;
}

// A and B of the split sum (Karis 2013) with pbr.h's visibility: for V at N.V = nv,
//   A = mean((1 - Fc) w), B = mean(Fc w),  Fc = (1 - V.H)^5,  w = 4 Vis (N.L)(V.H) / (N.H),
// over 256 GGX-sampled half vectors.
std::vector<glm::vec2> brdf_lut() {
    constexpr int n = EnvironmentLighting::kLutSize;
    constexpr uint32_t kSamples = 256;
    std::vector<glm::vec2> lut(size_t(n) * size_t(n));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double nv = (i + 0.5) / n, roughness = std::max(0.03, (j + 0.5) / n);
            const double alpha = roughness * roughness, a2 = alpha * alpha;
            const glm::dvec3 v(std::sqrt(1.0 - nv * nv), 0.0, nv), normal(0, 0, 1);
            double a = 0.0, b = 0.0;
            for (uint32_t s = 0; s < kSamples; ++s) {
                const glm::dvec3 h = ggx_half_vector(hammersley(s, kSamples), a2, normal);
                const double vh = glm::dot(v, h);
                const glm::dvec3 l = 2.0 * vh * h - v;
                const double nl = l.z, nh = h.z;
                if (!(nl > 0.0) || !(vh > 0.0)) continue;
                const double vis = 1.0 / ((nl + std::sqrt(a2 + (1.0 - a2) * nl * nl)) * (nv + std::sqrt(a2 + (1.0 - a2) * nv * nv)));
                const double w = 4.0 * vis * nl * vh / nh, fc = std::pow(1.0 - vh, 5.0);
                a += (1.0 - fc) * w;
                b += fc * w;
            }
            lut[size_t(j) * n + size_t(i)] = glm::vec2(float(a / kSamples), float(b / kSamples));
        }
    return lut;
}

// The nine coefficients of E/pi: the picture projected on the spherical harmonics up to
// order 2 (each texel weighted by its solid angle), times A_0 = pi, A_1 = 2 pi / 3,
// A_2 = pi / 4, over pi, with each basis function's constant folded in.
std::array<glm::vec3, 9> irradiance(const EquirectImage& m) {
    std::array<glm::dvec3, 9> c{};
    for (int j = 0; j < m.height; ++j) {
        const double t = kPi * (j + 0.5) / m.height;
        const double solid_angle = (2.0 * kPi / m.width) * (kPi / m.height) * std::sin(t);
        for (int i = 0; i < m.width; ++i) {
            const glm::dvec3 d = texel_direction(i, j, m.width, m.height), l = glm::dvec3(m.at(i, j)) * solid_angle;
            const double x = d.x, y = d.y, z = d.z;
            const double basis[9] = {0.282095, 0.488603 * y, 0.488603 * z, 0.488603 * x, 1.092548 * x * y,
                                     1.092548 * y * z, 0.315392 * (3 * z * z - 1), 1.092548 * x * z, 0.546274 * (x * x - y * y)};
            for (size_t k = 0; k < 9; ++k) c[k] += l * basis[k];
        }
    }
    // Evaluating E = sum A_l c_k Y_k: each Y_k's constant once more, then / pi.
    const double constant[9] = {0.282095, 0.488603, 0.488603, 0.488603, 1.092548, 1.092548, 0.315392, 1.092548, 0.546274};
    const double band[9] = {kPi, 2 * kPi / 3, 2 * kPi / 3, 2 * kPi / 3, kPi / 4, kPi / 4, kPi / 4, kPi / 4, kPi / 4};
    std::array<glm::vec3, 9> out;
    for (size_t k = 0; k < 9; ++k) out[k] = glm::vec3(c[k] * (band[k] * constant[k] / kPi));
    return out;
}

// Whether a Radiance file holds all its scanlines. stb_image reads past the end of a cut
// file as zeros, so the check walks the scanlines first: after the header's blank line and
// the resolution line, each scanline is either run-length encoded (2, 2, width, then four
// channels of runs: a count over 128 repeats one byte, else that many bytes follow) or
// width flat RGBE texels.
bool radiance_complete(const std::string& b, int w, int h) {
    size_t at = b.find("\n\n");
    if (at == std::string::npos) return false;
    at = b.find('\n', at + 2);  // the end of the resolution line
    if (at == std::string::npos) return false;
    ++at;
    auto byte = [&](size_t k) { return static_cast<unsigned char>(b[k]); };
    for (int y = 0; y < h; ++y) {
        if (at + 4 <= b.size() && w >= 8 && w < 32768 && byte(at) == 2 && byte(at + 1) == 2 && (byte(at + 2) & 0x80) == 0) {
            at += 4;
            for (int c = 0; c < 4; ++c)
                for (int x = 0; x < w;) {
                    if (at >= b.size()) return false;
                    const int count = byte(at++);
                    if (count > 128) {
                        x += count - 128;
                        ++at;
                    } else {
                        if (count == 0) return false;
                        x += count;
                        at += size_t(count);
                    }
                }
        } else {
            at += 4 * size_t(w);
        }
        if (at > b.size()) return false;
    }
    return true;
}

}  // namespace

glm::vec2 equirect_uv(const glm::vec3& d) {
    return {0.5f + Sleef_cinz_atan2f1_u10purec(d.x, -d.z) * kInvTwoPi, Sleef_cinz_acosf1_u10purec(std::clamp(d.y, -1.0f, 1.0f)) * kInvPi};
}

EnvironmentLighting prepare_environment(const EquirectImage& picture, float intensity, bool background) {
    EnvironmentLighting e;
    e.intensity = intensity;
    e.background = background;
    if (background) e.picture = picture;  // (only the sky reads it: a large picture is not kept for nothing)
    std::vector<EquirectImage> pyramid{base_level(picture)};
    while (int(pyramid.size()) < EnvironmentLighting::kLevels) pyramid.push_back(half(pyramid.back()));
    e.irradiance = irradiance(pyramid[0]);
    e.specular.reserve(size_t(EnvironmentLighting::level_offset(EnvironmentLighting::kLevels)) + 2);
    for (int k = 0; k < EnvironmentLighting::kLevels; ++k) {
        const EquirectImage level = k == 0 ? pyramid[0] : prefilter(pyramid, k);
        e.specular.insert(e.specular.end(), level.texels.begin(), level.texels.end());
    }
    // (Padding: the eight-lane lookup loads a row's two texels and two floats more.)
    e.specular.insert(e.specular.end(), 2, glm::vec3(0.0f));
    e.lut = brdf_lut();
    return e;
}

EquirectImage read_environment(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::string ext = path.extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    EquirectImage out;
    if (ext == ".hdr") {
        const std::string bytes = read_whole_file(path);
        int w = 0, h = 0, channels = 0;
        float* data = stbi_loadf_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &w, &h, &channels, 3);
        if (!data) throw InputError(name + ": corrupt Radiance HDR (" + stbi_failure_reason() + ")");
        if (!radiance_complete(bytes, w, h)) {
            stbi_image_free(data);
            throw InputError(name + ": corrupt Radiance HDR (truncated)");
        }
        out = {w, h, std::vector<glm::vec3>(size_t(w) * size_t(h))};
        for (size_t k = 0; k < out.texels.size(); ++k) out.texels[k] = glm::vec3(data[3 * k], data[3 * k + 1], data[3 * k + 2]);
        stbi_image_free(data);
    } else if (ext == ".exr") {
        try {
            Imf::RgbaInputFile file(path.c_str());
            const Imath::Box2i dw = file.dataWindow();
            const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
            Imf::Array2D<Imf::Rgba> px(h, w);
            file.setFrameBuffer(&px[0][0] - dw.min.x - dw.min.y * w, 1, size_t(w));
            file.readPixels(dw.min.y, dw.max.y);
            out = {w, h, std::vector<glm::vec3>(size_t(w) * size_t(h))};
            for (int j = 0; j < h; ++j)
                for (int i = 0; i < w; ++i) out.texels[size_t(j) * size_t(w) + size_t(i)] = glm::vec3(px[j][i].r, px[j][i].g, px[j][i].b);
        } catch (const std::exception& e) {
            throw InputError(name + ": corrupt OpenEXR (" + e.what() + ")");
        }
    } else {
        throw InputError(name + ": an environment is an .hdr or .exr picture");
    }
    if (out.width < 2 || out.height < 1) throw InputError(name + ": the picture is too small for an environment");
    for (const glm::vec3& t : out.texels)
        if (!(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z)) || t.x < 0 || t.y < 0 || t.z < 0)
            throw InputError(name + ": an environment's texels are finite and not negative");
    return out;
}

}  // namespace softraster

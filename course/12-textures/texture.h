// Lesson 12: textures (纹理) and their filtering. Texture coordinates (u, v) run from 0 to 1
// across the picture, u to the right and v up (OpenGL's convention: texel row 0 is the bottom
// row); outside [0, 1] the texture repeats. Texel (i, j) has its center at ((i + 1/2) / W, (j + 1/2) / H).
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

namespace course {

struct TexelImage {
    int width = 0, height = 0;
    std::vector<glm::u8vec4> texels;  // row j = 0 at the bottom
    glm::vec4 at(int i, int j) const {  // repeat: wrap the index into the texture
        i = ((i % width) + width) % width, j = ((j % height) + height) % height;
        return glm::vec4(texels[size_t(j) * size_t(width) + size_t(i)]) / 255.0f;
    }
};

// Nearest (最近邻): the texel whose square holds (u, v).
inline glm::vec4 sample_nearest(const TexelImage& t, glm::vec2 uv) {
    return t.at(int(std::floor(uv.x * float(t.width))), int(std::floor(uv.y * float(t.height))));
}

// Bilinear (双线性): the four texels whose centers surround (u, v), each weighted by how near
// it is: two linear blends along u, then one along v.
inline glm::vec4 sample_bilinear(const TexelImage& t, glm::vec2 uv) {
    const float x = uv.x * float(t.width) - 0.5f, y = uv.y * float(t.height) - 0.5f;
    const int i = int(std::floor(x)), j = int(std::floor(y));
    const float fx = x - float(i), fy = y - float(j);
    const glm::vec4 bottom = t.at(i, j) * (1.0f - fx) + t.at(i + 1, j) * fx, top = t.at(i, j + 1) * (1.0f - fx) + t.at(i + 1, j + 1) * fx;
    return bottom * (1.0f - fy) + top * fy;
}

// Mipmaps (多级渐远纹理, Williams 1983): the texture at half the size, a quarter, ... down to
// one texel, each texel the average of the 2 x 2 under it (rounded to 8 bits). A pixel that
// covers many texels reads a level where it covers about one.
inline std::vector<TexelImage> mipmaps(const TexelImage& base) {
    std::vector<TexelImage> chain{base};
    while (chain.back().width > 1 || chain.back().height > 1) {
        const TexelImage& s = chain.back();
        TexelImage d{std::max(1, s.width / 2), std::max(1, s.height / 2), {}};
        for (int j = 0; j < d.height; ++j)
            for (int i = 0; i < d.width; ++i) {
                glm::uvec4 sum(2u);  // (+2: round to nearest)
                for (int dj = 0; dj < 2; ++dj)
                    for (int di = 0; di < 2; ++di)
                        sum += glm::uvec4(s.texels[size_t(std::min(2 * j + dj, s.height - 1)) * size_t(s.width) + size_t(std::min(2 * i + di, s.width - 1))]);
                d.texels.push_back(glm::u8vec4(sum / 4u));
            }
        chain.push_back(std::move(d));
    }
    return chain;
}

// The level of detail (细节层次): how many texels one pixel step covers, from the screen-space
// derivatives of (u, v), rho = max(|d(uv)/dx|, |d(uv)/dy|) in texels; lod = log2(rho).
inline float level_of_detail(const TexelImage& base, glm::vec2 duv_dx, glm::vec2 duv_dy) {
    const glm::vec2 size(base.width, base.height);
    const float rho = std::max(glm::length(duv_dx * size), glm::length(duv_dy * size));
    return std::log2(std::max(rho, 1e-12f));
}

// Trilinear (三线性): bilinear in the two levels around lod, blended by its fraction. Below
// lod 0 the texture is magnified: level 0, bilinear.
inline glm::vec4 sample_trilinear(const std::vector<TexelImage>& chain, glm::vec2 uv, float lod) {
    lod = std::clamp(lod, 0.0f, float(chain.size() - 1));
    const int lo = int(std::floor(lod)), hi = std::min(lo + 1, int(chain.size()) - 1);
    const float f = lod - float(lo);
    return sample_bilinear(chain[size_t(lo)], uv) * (1.0f - f) + sample_bilinear(chain[size_t(hi)], uv) * f;
}

}  // namespace course

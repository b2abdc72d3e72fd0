// A model file's materials through assimp: colors, alpha modes, sidedness, the base color
// texture with its sampler, glTF's metallic-roughness maps, and the textures themselves
// (embedded, or files beside the model).
#include "scene/model_materials.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <assimp/GltfMaterial.h>
#include <glm/common.hpp>

#include "softraster/error.h"
#include "softraster/io/image_io.h"

namespace softraster {

namespace fs = std::filesystem;

std::string lower_case(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

MaterialUse MaterialReader::read(const aiMaterial& m) {
    MaterialUse use;
    Material& mat = use.material;
    aiColor4D color(1, 1, 1, 1);
    if (m.Get(AI_MATKEY_BASE_COLOR, color) != AI_SUCCESS && m.Get(AI_MATKEY_COLOR_DIFFUSE, color) == AI_SUCCESS) {
        float opacity = 1.0f;
        if (m.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS) color.a = opacity;
    }
    mat.color = glm::clamp(glm::vec4(color.r, color.g, color.b, color.a), 0.0f, 1.0f);
    if (!std::isfinite(color.r + color.g + color.b + color.a)) mat.color = glm::vec4(1.0f);

    aiShadingMode shading = aiShadingMode_Gouraud;
    if (m.Get(AI_MATKEY_SHADING_MODEL, shading) == AI_SUCCESS && shading == aiShadingMode_Unlit)
        mat.shading = Shading::Unlit;

    aiString alpha_mode;
    if (m.Get(AI_MATKEY_GLTF_ALPHAMODE, alpha_mode) == AI_SUCCESS) {
        const std::string mode = alpha_mode.C_Str();
        if (mode == "BLEND") mat.blend = BlendMode::Alpha;
        if (mode == "MASK") {
            float cutoff = 0.5f;
            m.Get(AI_MATKEY_GLTF_ALPHACUTOFF, cutoff);
            mat.alpha_cutoff = std::isfinite(cutoff) ? cutoff : 0.5f;
        }
    } else if (mat.color.a <= 0.0f) {
        // Formats without alpha modes: opacity 0 would hide the object entirely. It is
        // nearly always an exporter's inverted convention (COLLADA's "transparency" 0
        // written to mean opaque), so such a material is drawn opaque, and said so.
        mat.color.a = 1.0f;
        ignored_.insert("opacity 0 (taken for an inverted convention: drawn opaque)");
    } else if (mat.color.a < 1.0f) {
        mat.blend = BlendMode::Alpha;  // translucent when 0 < opacity < 1
    }
    // Single-sided only where the file says so (glTF's doubleSided false); other formats
    // rarely state it and their windings are often inconsistent, so nothing is culled.
    int two_sided = 1;
    if (m.Get(AI_MATKEY_TWOSIDED, two_sided) == AI_SUCCESS && !two_sided) use.cull = CullMode::Back;

    for (aiTextureType type : {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE}) {
        aiString file;
        if (m.GetTextureCount(type) == 0 || m.GetTexture(type, 0, &file) != AI_SUCCESS) continue;
        m.Get(AI_MATKEY_UVWSRC(type, 0), use.uv_set);
        aiUVTransform transform;
        if (m.Get(AI_MATKEY_UVTRANSFORM(type, 0), transform) == AI_SUCCESS) use.transform = transform;
        auto wrap_mode = [&](aiTextureMapMode mode) {
            switch (mode) {
                case aiTextureMapMode_Clamp: return Wrap::Clamp;
                case aiTextureMapMode_Mirror: return Wrap::Mirror;
                case aiTextureMapMode_Decal: return Wrap::Border;  // (transparent black outside)
                default: return Wrap::Repeat;
            }
        };
        aiTextureMapMode wrap_u = aiTextureMapMode_Wrap, wrap_v = aiTextureMapMode_Wrap;
        m.Get(AI_MATKEY_MAPPINGMODE_U(type, 0), wrap_u);
        m.Get(AI_MATKEY_MAPPINGMODE_V(type, 0), wrap_v);
        mat.sampler.wrap_s = wrap_mode(wrap_u), mat.sampler.wrap_t = wrap_mode(wrap_v);
        // glTF's sampler filters (GL enums); without them, bilinear.
        int mag_filter = 0, min_filter = 0;
        if (m.Get(AI_MATKEY_GLTF_MAPPINGFILTER_MAG(type, 0), mag_filter) == AI_SUCCESS && mag_filter == 9728)
            mat.sampler.mag = Filter::Nearest;  // GL_NEAREST
        if (m.Get(AI_MATKEY_GLTF_MAPPINGFILTER_MIN(type, 0), min_filter) == AI_SUCCESS && min_filter >= 9728 && min_filter <= 9987) {
            // NEAREST 9728, LINEAR 9729, then {NEAREST, LINEAR}_MIPMAP_{NEAREST, LINEAR} 9984..9987
            const bool mip = min_filter >= 9984;
            const int k = mip ? min_filter - 9984 : min_filter - 9728;
            mat.sampler.min = (k & 1) ? Filter::Bilinear : Filter::Nearest;
            mat.sampler.mip = !mip ? MipFilter::None : ((k & 2) ? MipFilter::Linear : MipFilter::Nearest);
        }
        mat.texture = texture(file.C_Str(), /*color=*/true);
        break;
    }
    if (mat.shading != Shading::Unlit && m.Get(AI_MATKEY_GLTF_ALPHAMODE, alpha_mode) == AI_SUCCESS) read_pbr(m, use);
    if (mat.shading != Shading::Pbr) {
        if (m.GetTextureCount(aiTextureType_NORMALS) > 0) ignored_.insert("normal maps");
        if (m.GetTextureCount(aiTextureType_METALNESS) > 0 || m.GetTextureCount(aiTextureType_DIFFUSE_ROUGHNESS) > 0)
            ignored_.insert("metallic-roughness maps");
        if (m.GetTextureCount(aiTextureType_LIGHTMAP) > 0 || m.GetTextureCount(aiTextureType_AMBIENT_OCCLUSION) > 0)
            ignored_.insert("occlusion maps");
        if (m.GetTextureCount(aiTextureType_EMISSIVE) > 0) ignored_.insert("emissive maps");
    }
    return use;
}

// A glTF material (assimp's glTF 2 reader is the one that writes an alpha mode) is drawn
// as the file describes it: metallic-roughness (docs/scene-format.md "Physically based
// materials") with its factors, emissive color and strength, and the maps that read the
// base color texture's coordinate set (ours has one per object).
void MaterialReader::read_pbr(const aiMaterial& m, MaterialUse& use) {
    Material& mat = use.material;
    mat.shading = Shading::Pbr;
    auto factor = [](float v, float def) { return std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : def; };
    float metallic = 1.0f, roughness = 1.0f;  // glTF's defaults
    m.Get(AI_MATKEY_METALLIC_FACTOR, metallic);
    m.Get(AI_MATKEY_ROUGHNESS_FACTOR, roughness);
    mat.metallic = factor(metallic, 1.0f), mat.roughness = factor(roughness, 1.0f);
    aiColor3D emissive(0, 0, 0);
    float strength = 1.0f;
    m.Get(AI_MATKEY_COLOR_EMISSIVE, emissive);
    m.Get(AI_MATKEY_EMISSIVE_INTENSITY, strength);  // KHR_materials_emissive_strength
    const glm::vec3 e = glm::vec3(emissive.r, emissive.g, emissive.b) * strength;
    mat.emissive = std::isfinite(e.x + e.y + e.z) ? glm::clamp(e, 0.0f, 1e30f) : glm::vec3(0.0f);
    auto map = [&](aiTextureType type, bool color = false) -> std::shared_ptr<const Texture> {
        aiString file;
        if (m.GetTextureCount(type) == 0 || m.GetTexture(type, 0, &file) != AI_SUCCESS) return nullptr;
        unsigned uv_set = 0;
        m.Get(AI_MATKEY_UVWSRC(type, 0), uv_set);
        if (uv_set != use.uv_set) {
            ignored_.insert("maps on another texture coordinate set than the base color's");
            return nullptr;
        }
        return texture(file.C_Str(), color);
    };
    // (assimp's glTF 2 reader files the metallic-roughness texture as "unknown".)
    for (aiTextureType type : {aiTextureType_UNKNOWN, aiTextureType_METALNESS, aiTextureType_DIFFUSE_ROUGHNESS})
        if (!mat.metallic_roughness_texture) mat.metallic_roughness_texture = map(type);
    mat.occlusion_texture = map(aiTextureType_LIGHTMAP);
    if (mat.occlusion_texture) {
        float strength_ao = 1.0f;
        if (m.Get(AI_MATKEY_GLTF_TEXTURE_STRENGTH(aiTextureType_LIGHTMAP, 0), strength_ao) == AI_SUCCESS)
            mat.occlusion_strength = factor(strength_ao, 1.0f);
    }
    mat.emissive_texture = map(aiTextureType_EMISSIVE, /*color=*/true);
    mat.normal_texture = map(aiTextureType_NORMALS);
    if (mat.normal_texture) {
        float scale = 1.0f;
        m.Get(AI_MATKEY_GLTF_TEXTURE_SCALE(aiTextureType_NORMALS, 0), scale);
        mat.normal_scale = std::isfinite(scale) ? std::clamp(scale, -1e6f, 1e6f) : 1.0f;
    }
}

// A texture by the name the material gives: "*N" or a name assimp knows as embedded, else
// a file beside the model (Windows separators and absolute paths from the author's
// machine are common: the file name alone is tried last).
// Color textures (base color, emissive) take the scene's color space; the other maps are data.
std::shared_ptr<const Texture> MaterialReader::texture(const std::string& ref, bool color) {
    const ColorSpace space = color ? color_space_ : ColorSpace::Linear;
    auto [slot, fresh] = textures_.try_emplace({ref, space});
    if (!fresh) return slot->second;
    try {
        if (const aiTexture* embedded = scene_.GetEmbeddedTexture(ref.c_str())) {
            slot->second = std::make_shared<Texture>(embedded_image(*embedded, ref), space);
        } else {
            slot->second = std::make_shared<Texture>(read_image(texture_file(ref)), space);
        }
    } catch (const InputError& e) {
        if (missing_ == MissingTexture::Fail) throw InputError(name_ + ": " + "texture '" + ref + "': " + e.what());
        warnings_.push_back(name_ + ": texture '" + ref + "' not drawn (" + e.what() + ")");
    }
    return slot->second;
}

// Where a texture named `ref` is: beside the model as written (with Windows separators
// turned around); else its file name alone beside the model (paths from the author's
// machine); else the same name in another case (DOS-era formats write IMAGE1.JPG for
// image1.jpg). When none exists, the first, for the error message.
fs::path MaterialReader::texture_file(std::string ref) const {
    std::replace(ref.begin(), ref.end(), '\\', '/');
    const fs::path dir = path_.parent_path();
    const fs::path as_written = dir / ref;
    const fs::path name = fs::path(ref).filename();
    std::error_code ec;
    if (fs::exists(as_written, ec)) return as_written;
    if (name.empty()) return as_written;
    if (fs::exists(dir / name, ec)) return dir / name;
    const std::string wanted = lower_case(name.string());
    for (auto it = fs::directory_iterator(dir.empty() ? fs::path(".") : dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec))
        if (lower_case(it->path().filename().string()) == wanted) return it->path();
    return as_written;
}

Image MaterialReader::embedded_image(const aiTexture& t, const std::string& ref) const {
    const std::string label = name_ + " (embedded texture " + ref + ")";
    if (t.mHeight == 0) {  // compressed: mWidth bytes of a PNG, JPEG... file
        const std::string_view bytes(reinterpret_cast<const char*>(t.pcData), t.mWidth);
        std::string hint = lower_case(t.achFormatHint);
        const std::string ext = fs::path(t.mFilename.C_Str()).extension().string();
        if (hint.empty() && !ext.empty()) hint = lower_case(ext.substr(1));
        return read_image(bytes, label, hint);
    }
    if (uint64_t(t.mWidth) * t.mHeight > (uint64_t(1) << 28)) throw InputError(label + ": picture too large");
    Image img(int(t.mWidth), int(t.mHeight));
    for (size_t i = 0; i < img.pixels.size(); ++i) {
        const aiTexel& x = t.pcData[i];
        img.pixels[i] = {x.r, x.g, x.b, x.a};
    }
    return img;
}

}  // namespace softraster

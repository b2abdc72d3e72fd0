// A model file's materials, as model_assimp.cpp reads them (model_materials.cpp).
#pragma once
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <assimp/scene.h>

#include "softraster/image.h"
#include "softraster/scene/model.h"

namespace softraster {

// s in lower case (ASCII).
std::string lower_case(std::string s);

struct MaterialUse {
    Material material;
    CullMode cull = CullMode::None;
    unsigned uv_set = 0;                     // the texture coordinate set the base color texture reads
    std::optional<aiUVTransform> transform;  // KHR_texture_transform
};

// Reads the materials of one file, each texture once (textures shared between materials).
// Warnings (a texture not drawn) and what is not drawn at all go to the lists it is given.
class MaterialReader {
public:
    MaterialReader(const aiScene& scene, const std::filesystem::path& path, MissingTexture missing, ColorSpace color,
                   std::vector<std::string>& warnings, std::set<std::string>& ignored)
        : scene_(scene), path_(path), name_(path.string()), missing_(missing), color_space_(color), warnings_(warnings), ignored_(ignored) {}

    MaterialUse read(const aiMaterial& m);

private:
    void read_pbr(const aiMaterial& m, MaterialUse& use);
    std::shared_ptr<const Texture> texture(const std::string& ref, bool color = false);
    std::filesystem::path texture_file(std::string ref) const;
    Image embedded_image(const aiTexture& t, const std::string& ref) const;

    const aiScene& scene_;
    const std::filesystem::path path_;
    const std::string name_;
    const MissingTexture missing_;
    const ColorSpace color_space_;
    std::vector<std::string>& warnings_;
    std::set<std::string>& ignored_;
    std::map<std::pair<std::string, ColorSpace>, std::shared_ptr<const Texture>> textures_;
};

}  // namespace softraster

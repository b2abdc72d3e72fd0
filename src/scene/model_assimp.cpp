// Model files through assimp: its scene (meshes, materials, a node tree, embedded textures)
// becomes our objects. Each aiMesh is converted once and shared by every node that places it.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <assimp/GltfMaterial.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "io/read_file.h"
#include "scene/model_animation.h"
#include "scene/model_format.h"
#include "scene/model_materials.h"
#include "softraster/error.h"
#include "softraster/io/image_io.h"
#include "softraster/scene/model.h"

namespace softraster {
namespace {

namespace fs = std::filesystem;

// Deeper node trees than this are taken for a broken (or hostile) file.
constexpr int kMaxNodeDepth = 256;
// Objects a file may place in all (a node tree that instances a mesh exponentially often).
constexpr size_t kMaxObjects = 1u << 20;

std::string one_line(std::string s) {
    std::replace(s.begin(), s.end(), '\n', ' ');
    while (!s.empty() && (s.back() == ' ' || s.back() == '\r')) s.pop_back();
    return s;
}

// assimp's matrices are row-major (a1 a2 a3 a4 is the first row); glm's are column-major.
glm::mat4 to_glm(const aiMatrix4x4& m) {
    glm::mat4 r;
    for (unsigned row = 0; row < 4; ++row)
        for (unsigned col = 0; col < 4; ++col) r[int(col)][int(row)] = m[row][col];
    return r;
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// KHR_texture_transform as assimp stores it (aiUVTransform), back in glTF's terms, applied to
// texture coordinates. assimp flipped v (v' = 1 - v) and moved the rotation's center into
// mTranslation; undoing that gives glTF's offset o, rotation r and scale s, and glTF's
// uv' = T(o) R(r) S(s) uv in glTF's coordinates, v flipped around it. R turns the UVs
// counter-clockwise as the extension says, which with glTF's v pointing down is
// (u, v) -> (u cos r + v sin r, -u sin r + v cos r) (checked on the Khronos test model
// TextureTransformTest: the arrows point at the "correct" marks).
glm::vec2 apply_uv_transform(const aiUVTransform& t, glm::vec2 uv) {
    const float r = -t.mRotation;
    const float c = std::cos(r), s = std::sin(r);
    const glm::vec2 scale(t.mScaling.x, t.mScaling.y);
    const glm::vec2 offset(t.mTranslation.x - 0.5f * scale.x * (-c + s + 1.0f),
                           -(t.mTranslation.y - (0.5f * scale.y * (s + c - 1.0f) + 1.0f - scale.y)));
    const glm::vec2 g(uv.x * scale.x, (1.0f - uv.y) * scale.y);
    const glm::vec2 rotated(c * g.x + s * g.y, -s * g.x + c * g.y);
    const glm::vec2 moved = rotated + offset;
    return {moved.x, 1.0f - moved.y};
}

// assimp's message; importers turn std::bad_alloc into its what() text.
std::string importer_error(const Assimp::Importer& importer) {
    const std::string e = one_line(importer.GetErrorString());
    return e.find("bad_alloc") != std::string::npos ? "out of memory while importing" : e;
}

// The pointers and counts of an imported scene agree: every array a count promises exists and
// every index points inside its array (what the conversion below and assimp's later steps
// rely on). Broken files get here: importers pass some inconsistencies through.
void check_structure(const aiScene& scene, const std::string& name) {
    auto fail = [&](const std::string& what) { throw InputError(name + ": " + what); };
    if (!scene.mMeshes) fail("mesh list missing");
    if (scene.mNumMaterials > 0 && !scene.mMaterials) fail("material list missing");
    for (unsigned i = 0; i < scene.mNumMaterials; ++i)
        if (!scene.mMaterials[i]) fail("material " + std::to_string(i) + " missing");
    for (unsigned i = 0; i < scene.mNumMeshes; ++i) {
        const aiMesh* m = scene.mMeshes[i];
        const std::string which = "mesh " + std::to_string(i);
        if (!m) fail(which + " missing");
        if (m->mNumVertices > 0 && !m->mVertices) fail(which + ": positions missing");
        if (m->mNumFaces > 0 && !m->mFaces) fail(which + ": faces missing");
        if (m->mMaterialIndex >= scene.mNumMaterials) fail(which + ": material index out of range");
        for (unsigned f = 0; f < m->mNumFaces; ++f) {
            const aiFace& face = m->mFaces[f];
            if (face.mNumIndices == 0 || !face.mIndices) fail(which + ": face " + std::to_string(f) + " has no indices");
            for (unsigned k = 0; k < face.mNumIndices; ++k)
                if (face.mIndices[k] >= m->mNumVertices) fail(which + ": face " + std::to_string(f) + " has an index out of range");
        }
    }
    // The node tree, without recursion (a hostile file can be deep) and with a bound on its size.
    std::vector<std::pair<const aiNode*, int>> stack{{scene.mRootNode, 0}};
    size_t visited = 0;
    while (!stack.empty()) {
        const auto [node, depth] = stack.back();
        stack.pop_back();
        if (!node) fail("a node of the scene tree is missing");
        if (depth > kMaxNodeDepth) fail("node tree deeper than " + std::to_string(kMaxNodeDepth) + " levels (recursive nodes?)");
        if (++visited > kMaxObjects) fail("more than " + std::to_string(kMaxObjects) + " nodes");
        if (node->mNumMeshes > 0 && !node->mMeshes) fail("node '" + std::string(node->mName.C_Str()) + "': mesh list missing");
        for (unsigned i = 0; i < node->mNumMeshes; ++i)
            if (node->mMeshes[i] >= scene.mNumMeshes) fail("node '" + std::string(node->mName.C_Str()) + "' names a mesh out of range");
        if (node->mNumChildren > 0 && !node->mChildren) fail("node '" + std::string(node->mName.C_Str()) + "': child list missing");
        for (unsigned i = 0; i < node->mNumChildren; ++i) stack.push_back({node->mChildren[i], depth + 1});
    }
}

// What a material needs from the mesh it is drawn on.
class Loader {
public:
    Loader(const aiScene& scene, const fs::path& path, MissingTexture missing, ColorSpace color)
        : scene_(scene), path_(path), name_(path.string()), materials_reader_(scene, path, missing, color, model_.warnings, ignored_) {}

    Model load() {
        for (unsigned i = 0; i < scene_.mNumMaterials; ++i) materials_.push_back(read_material(*scene_.mMaterials[i]));
        for (unsigned i = 0; i < scene_.mNumMeshes; ++i) meshes_.push_back(read_mesh(i));
        motions_ = read_node_motions(scene_, ignored_);
        place(*scene_.mRootNode, glm::mat4(1.0f), {});
        if (model_.objects.empty()) fail("nothing to draw (no triangles, lines or points)");
        for (unsigned i = 0; i < scene_.mNumCameras; ++i) read_camera(*scene_.mCameras[i]);
        // Lights as glTF's KHR_lights_punctual defines them; other formats' lights have
        // other falloffs and units (a default rig is used for them).
        if (gltf()) for (unsigned i = 0; i < scene_.mNumLights; ++i) read_light(*scene_.mLights[i]);
        note_ignored();
        return std::move(model_);
    }

private:
    [[noreturn]] void fail(const std::string& what) const { throw InputError(name_ + ": " + what); }

    MaterialUse read_material(const aiMaterial& m) { return materials_reader_.read(m); }

    struct MeshUse {
        std::shared_ptr<const Mesh> mesh;  // none: nothing drawable
        Topology primitive = Topology::Triangles;
    };

    MeshUse read_mesh(unsigned index) {
        const aiMesh& in = *scene_.mMeshes[index];
        const std::string which = "mesh " + std::to_string(index) + (in.mName.length ? " ('" + std::string(in.mName.C_Str()) + "')" : "");
        const MaterialUse& use = materials_[in.mMaterialIndex];
        if (in.mNumBones > 0) ignored_.insert("skins (drawn in the bind pose)");
        if (in.mNumAnimMeshes > 0) ignored_.insert("morph targets");
        auto mesh = std::make_shared<Mesh>();
        MeshUse out;
        const aiVector3D* uvs = in.HasTextureCoords(use.uv_set) ? in.mTextureCoords[use.uv_set] : nullptr;
        bool good_normals = in.HasNormals();
        mesh->vertices.resize(in.mNumVertices);
        for (unsigned i = 0; i < in.mNumVertices; ++i) {
            MeshVertex& v = mesh->vertices[i];
            v.position = {in.mVertices[i].x, in.mVertices[i].y, in.mVertices[i].z};
            if (!finite(v.position)) fail(which + ": vertex " + std::to_string(i) + " has a non-finite position");
            if (good_normals) {
                v.normal = {in.mNormals[i].x, in.mNormals[i].y, in.mNormals[i].z};
                good_normals = finite(v.normal) && glm::dot(v.normal, v.normal) > 0.0f;
            }
            if (uvs) {
                v.uv = {uvs[i].x, uvs[i].y};
                if (use.transform) v.uv = apply_uv_transform(*use.transform, v.uv);
                if (!std::isfinite(v.uv.x) || !std::isfinite(v.uv.y)) v.uv = glm::vec2(0.0f);
            }
            if (in.HasVertexColors(0)) {
                const aiColor4D& c = in.mColors[0][i];
                v.color = glm::clamp(glm::vec4(c.r, c.g, c.b, c.a), 0.0f, 1.0f);
                if (!std::isfinite(c.r + c.g + c.b + c.a)) v.color = glm::vec4(1.0f);
            }
        }
        if (in.GetNumColorChannels() > 1 || in.GetNumUVChannels() > 1) ignored_.insert("extra vertex color or texture coordinate sets");
        std::vector<uint32_t> indices;
        unsigned corners = 0;
        for (unsigned f = 0; f < in.mNumFaces; ++f) {
            const aiFace& face = in.mFaces[f];
            if (corners == 0) corners = face.mNumIndices;
            if (face.mNumIndices != corners) continue;  // (SortByPType leaves one kind per mesh)
            for (unsigned k = 0; k < face.mNumIndices; ++k) {
                if (face.mIndices[k] >= in.mNumVertices) fail(which + ": face " + std::to_string(f) + " has an index out of range");
                indices.push_back(face.mIndices[k]);
            }
        }
        if (in.mNumFaces == 0 && in.mNumVertices > 0) {  // a point cloud: every vertex a point
            corners = 1;
            for (unsigned i = 0; i < in.mNumVertices; ++i) indices.push_back(i);
        }
        if (indices.empty() || corners == 0 || corners > 3) return out;
        if (corners == 3 && !good_normals) {
            // No usable normals: each triangle gets its face normal (the scene format's rule).
            const std::vector<MeshVertex> shared = std::move(mesh->vertices);
            mesh->vertices.clear();
            for (size_t t = 0; t + 2 < indices.size(); t += 3)
                mesh->add_face_normal_triangle(shared[indices[t]], shared[indices[t + 1]], shared[indices[t + 2]]);
        } else if (corners == 3) {
            mesh->indices = std::move(indices);
            if (in.HasTangentsAndBitangents()) read_tangents(in, *mesh);
        } else if (corners == 2) {
            mesh->lines = std::move(indices);
            out.primitive = Topology::Lines;
        } else {
            mesh->points = std::move(indices);
            out.primitive = Topology::Points;
        }
        out.mesh = std::move(mesh);
        return out;
    }

    // The file's tangents (glTF TANGENT), all of them usable, or none: the scene's own are
    // generated where a normal map needs them (add_tangents). assimp gives the bitangent
    // w · cross(N, T); its side of the tangent plane is w.
    static void read_tangents(const aiMesh& in, Mesh& mesh) {
        std::vector<TangentVertex> out(mesh.vertices.size());
        for (size_t i = 0; i < out.size(); ++i) {
            const glm::vec3 t(in.mTangents[i].x, in.mTangents[i].y, in.mTangents[i].z), b(in.mBitangents[i].x, in.mBitangents[i].y, in.mBitangents[i].z);
            const glm::vec3 n = mesh.vertices[i].normal;
            if (!finite(t) || !finite(b) || !(glm::dot(t, t) > 0.0f)) return;
            out[i] = TangentVertex::of(mesh.vertices[i], glm::vec4(t, glm::dot(glm::cross(n, t), b) < 0.0f ? -1.0f : 1.0f));
        }
        mesh.tangent_vertices = std::move(out);
    }

    // `chain`: the links from the root to the parent once a node on the way is animated
    // (empty before: then `parent` is all there is).
    void place(const aiNode& node, const glm::mat4& parent, const std::vector<MotionLink>& chain) {
        // (check_structure bounded the depth and the indices.)
        const glm::mat4 local = to_glm(node.mTransformation), world = parent * local;
        if (!finite(world)) fail("node '" + std::string(node.mName.C_Str()) + "' has a non-finite transform");
        world_[node.mName.C_Str()] = world;
        std::vector<MotionLink> links = chain;
        const auto moved = motions_.find(node.mName.C_Str());
        if (moved != motions_.end()) {
            if (links.empty()) links.push_back({glm::dmat4(parent), nullptr});
            links.push_back({glm::dmat4(1.0), moved->second});
        } else if (!links.empty() && !links.back().motion) {
            links.back().fixed = links.back().fixed * glm::dmat4(local);
        } else if (!links.empty()) {
            links.push_back({glm::dmat4(local), nullptr});
        }
        std::shared_ptr<const ObjectMotion> motion;
        if (!links.empty() && node.mNumMeshes > 0) motion = std::make_shared<ObjectMotion>(ObjectMotion{links});
        for (unsigned i = 0; i < node.mNumMeshes; ++i) {
            const aiMesh& in = *scene_.mMeshes[node.mMeshes[i]];
            const MeshUse& mesh = meshes_[node.mMeshes[i]];
            if (!mesh.mesh) continue;
            if (model_.objects.size() >= kMaxObjects) fail("more than " + std::to_string(kMaxObjects) + " mesh instances");
            SceneObject o;
            o.mesh = mesh.mesh;
            o.model = world;
            o.motion = motion;
            const MaterialUse& use = materials_[in.mMaterialIndex];
            o.material = use.material;
            o.cull = use.cull;
            o.primitive = mesh.primitive;
            model_.objects.push_back(std::move(o));
        }
        for (unsigned i = 0; i < node.mNumChildren; ++i) place(*node.mChildren[i], world, links);
    }

    // An assimp camera looks from mPosition along mLookAt with mUp, in its node's space;
    // mHorizontalFOV is half the horizontal angle, mOrthographicWidth half the width.
    void read_camera(const aiCamera& c) {
        const auto node = world_.find(c.mName.C_Str());
        const glm::mat4 m = node != world_.end() ? node->second : glm::mat4(1.0f);
        Camera cam;
        cam.eye = glm::vec3(m * glm::vec4(c.mPosition.x, c.mPosition.y, c.mPosition.z, 1.0f));
        cam.target = cam.eye + glm::vec3(m * glm::vec4(c.mLookAt.x, c.mLookAt.y, c.mLookAt.z, 0.0f));
        cam.up = glm::vec3(m * glm::vec4(c.mUp.x, c.mUp.y, c.mUp.z, 0.0f));
        const float aspect = c.mAspect > 0.0f ? c.mAspect : 4.0f / 3.0f;
        cam.orthographic = c.mOrthographicWidth > 0.0f;
        cam.fov_y = glm::degrees(2.0f * std::atan(std::tan(c.mHorizontalFOV) / aspect));
        cam.height = 2.0f * c.mOrthographicWidth / aspect;
        cam.near = c.mClipPlaneNear > 0.0f ? c.mClipPlaneNear : 0.1f;
        cam.far = c.mClipPlaneFar > cam.near ? c.mClipPlaneFar : cam.near * 1000.0f;
        const bool usable = finite(cam.eye) && finite(cam.target) && finite(cam.up) && cam.eye != cam.target &&
                            std::isfinite(cam.fov_y) && cam.fov_y > 0.0f && cam.fov_y < 180.0f &&
                            (!cam.orthographic || (std::isfinite(cam.height) && cam.height > 0.0f));
        if (usable) model_.cameras.push_back(cam);
        else ignored_.insert("a camera with unusable parameters");
    }

    // A light of the file at its node (glTF's KHR_lights_punctual as assimp reads it: the
    // color already times the intensity, cone angles in radians, the range not kept).
    void read_light(const aiLight& l) {
        const auto node = world_.find(l.mName.C_Str());
        const glm::mat4 m = node != world_.end() ? node->second : glm::mat4(1.0f);
        const glm::vec3 color(l.mColorDiffuse.r, l.mColorDiffuse.g, l.mColorDiffuse.b);
        const glm::vec3 position(m * glm::vec4(l.mPosition.x, l.mPosition.y, l.mPosition.z, 1.0f));
        const glm::vec3 direction(m * glm::vec4(l.mDirection.x, l.mDirection.y, l.mDirection.z, 0.0f));
        const bool usable = finite(color) && color.x >= 0 && color.y >= 0 && color.z >= 0 && std::max({color.x, color.y, color.z}) < 1e30f &&
                            finite(position) && finite(direction) &&
                            (l.mType == aiLightSource_POINT || glm::length(direction) > 0.0f);  // (a point light has none)
        const bool spot = l.mType == aiLightSource_SPOT;
        if (!usable || (l.mType != aiLightSource_DIRECTIONAL && l.mType != aiLightSource_POINT && !spot)) {
            ignored_.insert("a light of a kind or with values not drawn");
            return;
        }
        if (l.mType == aiLightSource_DIRECTIONAL) {
            if (model_.lights.directional.size() < Lights::kMaxDirectional) model_.lights.directional.push_back({direction, color, {}});
            else ignored_.insert("directional lights past the eighth");
            return;
        }
        if (model_.lights.punctual.size() >= Lights::kMaxPunctual) {
            ignored_.insert("point and spot lights past the 256th");
            return;
        }
        PunctualLight p;
        p.spot = spot;
        p.position = position;
        p.direction = direction;
        p.color = color;
        if (spot) {
            const float outer = glm::degrees(l.mAngleOuterCone), inner = glm::degrees(l.mAngleInnerCone);
            p.outer_angle = std::isfinite(outer) && outer > 0.0f ? std::min(outer, 90.0f) : 45.0f;
            p.inner_angle = std::isfinite(inner) && inner >= 0.0f && inner < p.outer_angle ? inner : 0.0f;
        }
        model_.lights.punctual.push_back(p);
    }

    bool gltf() const {
        const std::string ext = lower_case(path_.extension().string());
        return ext == ".gltf" || ext == ".glb";
    }

    void note_ignored() {
        if (scene_.mNumLights > 0 && !gltf()) ignored_.insert("the file's lights (a default rig is used)");
        for (const std::string& what : ignored_) model_.ignored.push_back(what);
    }

    const aiScene& scene_;
    const fs::path path_;
    const std::string name_;
    Model model_;
    std::set<std::string> ignored_;
    MaterialReader materials_reader_;  // (after model_ and ignored_, which it adds to)
    std::vector<MaterialUse> materials_;
    std::vector<MeshUse> meshes_;
    std::map<std::string, glm::mat4> world_;  // node name -> world transform (for cameras)
    std::map<std::string, std::shared_ptr<const NodeMotion>> motions_;  // node name -> its animation
};

}  // namespace

Model load_model(const fs::path& path, MissingTexture missing, ColorSpace color) {
    const std::string name = path.string();
    std::error_code ec;
    if (!fs::exists(path, ec)) throw InputError(name + ": file not found");
    if (fs::is_directory(path, ec)) throw InputError(name + ": is a directory");
    // The format the bytes show where the extension names another or none (model_format.h):
    // then read from memory as that format. (Files it refers to by relative paths, such as
    // a glTF's buffers and textures, are then looked for beside the program's folder, not
    // the file's: a misnamed file with sidecars may come out untextured.)
    const bool known = is_model_file(path);
    const std::string ext = lower_case(path.extension().string()), content = model_format_of_content(path, known);
    const bool misnamed = !content.empty() && content != ext;
    if (!known && !misnamed) throw InputError(name + ": not a model file assimp reads (neither its extension nor its first bytes show one)");
    Assimp::Importer importer;
    importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);
    std::string bytes;
    if (misnamed) bytes = read_whole_file(path);
    const aiScene* scene = misnamed ? importer.ReadFileFromMemory(bytes.data(), bytes.size(), 0, content.c_str() + 1) : importer.ReadFile(name, 0);
    if (!scene) throw InputError(name + ": " + importer_error(importer));
    if ((scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !scene->mRootNode || scene->mNumMeshes == 0)
        throw InputError(name + ": nothing to draw (the file has no meshes)");
    // Our own structural checks rather than assimp's validation step, which also rejects
    // what we can draw (point clouds: meshes without faces) or ignore (lights without nodes).
    check_structure(*scene, name);
    // Then polygons become triangles and each mesh is left with one primitive type.
    scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_SortByPType);
    if (!scene) throw InputError(name + ": " + importer_error(importer));
    Model model = Loader(*scene, path, missing, color).load();
    add_tangents(model.objects);
    return model;
}

bool is_model_file(const fs::path& path) {
    const std::string ext = lower_case(path.extension().string());
    if (ext.size() < 2 || ext == ".json") return false;
    static const Assimp::Importer importer;  // (only asked which extensions it knows)
    return importer.IsExtensionSupported(ext);
}

}  // namespace softraster

#include "scene/model_animation.h"

#include <cmath>

#include <glm/gtc/quaternion.hpp>

namespace softraster {

namespace {

bool finite(const aiVector3D& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// One kind of key (aiVectorKey or aiQuatKey) into a track: times in seconds.
template <class Key, class V, class Convert>
bool read_track(const Key* keys, unsigned count, double ticks_per_second, Track<V>& track, Convert convert) {
    if (count > 0 && !keys) return false;
    for (unsigned i = 0; i < count; ++i) {
        const double time = keys[i].mTime / ticks_per_second;
        if (!std::isfinite(time) || (i > 0 && !(time > track.times.back()))) return false;
        V value;
        if (!convert(keys[i].mValue, value)) return false;
        track.times.push_back(time);
        track.values.push_back(value);
    }
    return true;
}

}  // namespace

std::map<std::string, std::shared_ptr<const NodeMotion>> read_node_motions(const aiScene& scene, std::set<std::string>& ignored) {
    std::map<std::string, std::shared_ptr<const NodeMotion>> out;
    if (scene.mNumAnimations == 0 || !scene.mAnimations || !scene.mAnimations[0] || !scene.mRootNode) return out;
    if (scene.mNumAnimations > 1) ignored.insert("animations after the first");
    const aiAnimation& a = *scene.mAnimations[0];
    if (a.mNumMeshChannels > 0 || a.mNumMorphMeshChannels > 0) ignored.insert("mesh and morph target animations (drawn at rest)");
    // assimp keeps times in ticks; glTF's importer uses 1000 a second. 0 means unknown,
    // for which assimp's own viewer assumes 25.
    const double ticks = a.mTicksPerSecond > 0.0 ? a.mTicksPerSecond : 25.0;
    auto vec3 = [](const aiVector3D& v, glm::dvec3& value) {
        value = glm::dvec3(v.x, v.y, v.z);
        return finite(v);
    };
    auto quat = [](const aiQuaternion& q, glm::dquat& value) {
        const glm::dquat r(q.w, q.x, q.y, q.z);
        const double length = glm::length(r);
        if (!std::isfinite(length) || length < 1e-12) return false;
        value = r / length;
        return true;
    };
    for (unsigned i = 0; i < a.mNumChannels && a.mChannels; ++i) {
        const aiNodeAnim* c = a.mChannels[i];
        const aiNode* node = c ? scene.mRootNode->FindNode(c->mNodeName) : nullptr;
        if (!node) continue;  // (a channel of no node moves nothing)
        auto m = std::make_shared<NodeMotion>();
        // The rest pose of what the channel leaves alone: the node's own transform.
        aiVector3D scale, position;
        aiQuaternion rotation;
        node->mTransformation.Decompose(scale, rotation, position);
        glm::dquat rest;
        const bool usable = vec3(position, m->rest_translate) && vec3(scale, m->rest_scale) && quat(rotation, rest) &&
                            read_track(c->mPositionKeys, c->mNumPositionKeys, ticks, m->translate, vec3) &&
                            read_track(c->mRotationKeys, c->mNumRotationKeys, ticks, m->rotation, quat) &&
                            read_track(c->mScalingKeys, c->mNumScalingKeys, ticks, m->scale, vec3);
        if (!usable) {
            ignored.insert("an animation channel with unusable keys (its node drawn at rest)");
            continue;
        }
        m->rest_rotation = glm::mat4_cast(rest);
        out[c->mNodeName.C_Str()] = std::move(m);
    }
    return out;
}

}  // namespace softraster

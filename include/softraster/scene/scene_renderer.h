// Draws a Scene: everything that does not change between frames (matrices, lights, the
// flat-shading buffers, the draw order) is prepared once, then render() draws a frame.
//
// This header stays light (no pipeline templates): the draws are recorded in
// scene_renderer.cpp and src/scene/record_surface_draw.h.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "softraster/framebuffer.h"
#include "softraster/image.h"
#include "softraster/render_state.h"
#include "softraster/scene/scene.h"
#include "softraster/shading/surface_uniforms.h"

namespace softraster {

class Context;
class WorkerPool;

struct RenderStats {
    uint64_t fragments_shaded = 0;  // fragment shader runs
};

class SceneRenderer {
public:
    // threads: how many threads draw (1 = all on the calling thread). It keeps a reference
    // to the scene, which must outlive it: a temporary only within one expression.
    explicit SceneRenderer(const Scene& scene, unsigned threads = 1);
    ~SceneRenderer();
    SceneRenderer(const SceneRenderer&) = delete;
    SceneRenderer& operator=(const SceneRenderer&) = delete;

    // Draws the shadow maps and ambient occlusion's depth, then clears fb and draws every object in the spec's draw order. The draws are recorded on
    // the first call and replayed after, so buffers are reused from frame to frame; fb must
    // have the scene's sample count. Not for use by two threads at once.
    RenderStats render(Framebuffer& fb) const;
    // A framebuffer for render(fb): the scene's size times its supersampling factor, and its samples.
    Framebuffer make_framebuffer() const;
    // Whether fb is such a framebuffer (size, samples, color space), so that it can be reused.
    bool fits(const Framebuffer& fb) const;
    // The picture of a rendered framebuffer: the MSAA resolve, ambient occlusion, then the
    // supersampling box filter.
    Image resolve(const Framebuffer& fb) const;
    // Allocates a framebuffer, renders and resolves.
    Image render() const;

    const Scene& scene() const { return scene_; }
    // Its threads (null with one): for the work around a frame, such as resolve(fb, out, pool).
    WorkerPool* pool() const { return pool_.get(); }
    size_t triangle_count() const;

    // One object, ready to draw.
    struct Draw {
        const Mesh* mesh = nullptr;          // the object's mesh, or `flat_mesh`
        std::shared_ptr<Mesh> flat_mesh;     // flat shading: corners carry world face normals
        // Lines and points (drawn unlit): their indices into the mesh (primitive_indices).
        Topology primitive = Topology::Triangles;
        std::shared_ptr<const std::vector<uint32_t>> line_point_indices;
        SurfaceUniforms uniforms;
        RenderState state;
        Shading shading = Shading::Lambert;
        bool colored = false;                // the mesh has vertex colors other than white
    };
    const std::vector<Draw>& draws() const { return draws_; }

private:
    struct ShadowPass;  // a light's shadow map and the depth pass that fills it (scene_renderer.cpp)
    struct Sky;         // the environment behind the scene (sky_shader.h)
    struct OcclusionPass;  // the depth pass of ambient occlusion (ambient_occlusion.h)
    const Scene& scene_;
    std::vector<PositionalLight> positional_lights_;  // the draws' LightSets point here
    std::vector<std::unique_ptr<ShadowPass>> shadow_passes_;  // and here; drawn first in each frame
    std::unique_ptr<Sky> sky_;                                // drawn right after the clear
    std::unique_ptr<OcclusionPass> occlusion_;                // drawn before the frame, applied in resolve()
    std::vector<Draw> draws_;  // in draw order
    std::unique_ptr<WorkerPool> pool_;
    mutable std::unique_ptr<Context> ctx_;  // the recorded frame
};

inline Image render_scene(const Scene& scene) { return SceneRenderer(scene).render(); }

}  // namespace softraster

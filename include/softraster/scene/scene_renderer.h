// Draws a Scene: everything that does not change between frames (matrices, lights, the
// flat-shading buffers, the draw order) is prepared once, then render() draws a frame.
#pragma once
#include <memory>
#include <vector>

#include "softraster/framebuffer.h"
#include "softraster/scene/scene.h"
#include "softraster/shading/surface_shader.h"

namespace softraster {

class SceneRenderer {
public:
    explicit SceneRenderer(const Scene& scene);

    // Clears fb and draws every object in the spec's draw order.
    void render(Framebuffer& fb) const;
    // Allocates a framebuffer of the scene's size and samples, renders and resolves.
    Image render() const;

    const Scene& scene() const { return scene_; }
    size_t triangle_count() const;

    // One object, ready to draw.
    struct Draw {
        const Mesh* mesh;                    // the object's mesh, or `flat_mesh`
        std::shared_ptr<Mesh> flat_mesh;     // flat shading: corners carry world face normals
        SurfaceUniforms uniforms;
        RenderState state;
        Shading shading;
    };
    const std::vector<Draw>& draws() const { return draws_; }

private:
    const Scene& scene_;
    std::vector<Draw> draws_;  // in draw order
};

inline Image render_scene(const Scene& scene) { return SceneRenderer(scene).render(); }

}  // namespace softraster

// The library's front door: a Context records draws into a Framebuffer and runs them.
//
//   Framebuffer fb(640, 480);
//   Context ctx(fb);                       // or Context ctx(fb, &pool) to use worker threads
//   ctx.clear(glm::vec4(0, 0, 0, 1));
//   ctx.state.cull = CullMode::None;
//   ctx.draw(Topology::Triangles, my_shader, vertices, indices);
//   Image picture = ctx.read_pixels();      // runs what was recorded, then resolves
//
// Draws are recorded, not run at once: the vertex and index data and whatever the shader
// points to must stay alive until finish() (or read_pixels()). Running many draws at once
// (the whole frame, or a batch of a few hundred: Context::batching) is what lets them be
// split over threads: vertex processing -> primitive assembly -> clipping -> perspective
// divide & viewport -> culling -> binning into tiles, then per tile, in draw order: triangle
// setup -> rasterization -> fragment shading -> output merge. The picture does not depend on
// the number of threads, nor on the batches.
#pragma once
#include <cstddef>
#include <memory>
#include <new>
#include <span>
#include <vector>

#include "softraster/framebuffer.h"
#include "softraster/pipeline/draw_commands.h"
#include "softraster/render_state.h"
#include "softraster/worker_pool.h"

namespace softraster {

// Calls f.template operator()<Samples>() with the framebuffer's sample count (1 or 4: the
// fast back end's) as a compile-time constant, so inner loops never branch on it.
template <class F>
void dispatch_samples(int samples, F&& f) {
    if (samples == 4) f.template operator()<4>();
    else f.template operator()<1>();
}

class Context {
public:
    // pool: worker threads to use (nullptr: everything on the calling thread).
    explicit Context(Framebuffer& fb, WorkerPool* pool = nullptr) : fb_(&fb), pool_(pool) {}

    RenderState state;  // applies to the draws recorded after it is set

    // How execute() splits the recorded commands into batches, each run through the whole
    // pipeline (front end, then the tiles) before the next, as llvmpipe rasterizes its scene
    // when the bins fill. Thousands of small draws write far more post-transform vertices
    // than the caches hold; in batches, the tiles read them back while they are still
    // cached. A batch closes once it holds at least `draws` commands and `bytes` of
    // post-transform vertices. (The draw count keeps scenes of a few big meshes in one
    // batch: a tile's run of draws in two passes, hidden_surface_removal.h, ends where its
    // batch ends.) The picture is the same for any split; docs/performance.md has the numbers.
    struct Batching {
        size_t bytes = size_t(2) << 20;
        size_t draws = 256;
    };
    Batching batching;

    // Clears color, depth and (if the framebuffer has one) stencil.
    void clear(const glm::vec4& color, float depth = 1.0f, uint8_t stencil = 0) {
        commands_.push_back(std::make_unique<ClearCommand>(color, depth, stencil));
    }
    // Clears depth only: color and stencil keep what they hold.
    void clear_depth(float depth = 1.0f) { commands_.push_back(std::make_unique<ClearCommand>(depth)); }

    // Records a draw of `indices` (three per triangle, two per line, one per point).
    // Throws std::out_of_range for an index past the end of `vertices`.
    // Lines and points are drawn as two triangles each (line_point_quads.h).
    template <Shader S>
    void draw(Topology topology, const S& shader, std::span<const typename S::Vertex> vertices,
              std::span<const uint32_t> indices) {
        switch (topology) {
            case Topology::Triangles: return record<Topology::Triangles>(shader, vertices, indices);
            case Topology::Lines: return record<Topology::Lines>(shader, vertices, indices);
            case Topology::Points: return record<Topology::Points>(shader, vertices, indices);
        }
    }
    // The same for triangles only: a caller that draws nothing else compiles no line and
    // point code for its shaders.
    template <Shader S>
    void draw_triangles(const S& shader, std::span<const typename S::Vertex> vertices, std::span<const uint32_t> indices) {
        record<Topology::Triangles>(shader, vertices, indices);
    }

    // Runs the recorded commands; they stay recorded, so execute() again draws the same
    // frame again (reusing every buffer). finish() runs them and forgets them.
    void execute();
    void finish() {
        execute();
        commands_.clear();
    }
    // finish(), then the resolved picture.
    Image read_pixels() {
        finish();
        return fb_->read_pixels();
    }

    // Draws into another framebuffer of the same sample count and color space from now on.
    void set_framebuffer(Framebuffer& fb) { fb_ = &fb; }
    Framebuffer& framebuffer() { return *fb_; }
    uint64_t fragments_shaded() const { return fragments_shaded_; }  // by the last execute()
    size_t batches() const { return batches_; }                      // run by the last execute()

private:
    template <Topology T, Shader S>
    void record(const S& shader, std::span<const typename S::Vertex> vertices, std::span<const uint32_t> indices) {
        validate_indices(indices, vertices.size(), T);
        if (needs_general_back_end(state, fb_->samples(), fb_->srgb())) {
            commands_.push_back(
                std::make_unique<GeneralTriangleCommand<S, T>>(shader, state, fb_->samples(), fb_->color_space(), vertices, indices));
            return;
        }
        dispatch_samples(fb_->samples(), [&]<int Samples>() {
            commands_.push_back(std::make_unique<TriangleCommand<S, Samples, T>>(shader, state, vertices, indices));
        });
    }
    using Commands = std::span<const std::unique_ptr<Command>>;
    void execute_batch(Commands batch, const DrawTarget& target);
    void list_commands_by_tile(Commands batch, const TileGrid& grid);

    Framebuffer* fb_;
    WorkerPool* pool_;
    std::vector<uint32_t> owners_;  // per thread: the owner of each sample of its tile
    std::vector<std::unique_ptr<Command>> commands_;
    // Each tile's commands of the batch in draw order: tile t's are tile_commands_[tile_first_[t]
    // .. tile_first_[t + 1]). Built after binning, so a tile visits only the draws that touch
    // it; busy_tiles_ lists the tiles that have any, the back end's work items.
    std::vector<uint32_t> tile_first_;
    std::vector<Command*> tile_commands_;
    std::vector<uint32_t> busy_tiles_;
    uint64_t fragments_shaded_ = 0;
    size_t batches_ = 0;
    // The batch's post-transform vertices (Command::prepare): as big as the biggest batch's.
    struct AlignedDelete {
        void operator()(std::byte* p) const { ::operator delete(p, std::align_val_t(64)); }
    };
    std::unique_ptr<std::byte[], AlignedDelete> post_transform_;
    size_t post_transform_size_ = 0;
};

}  // namespace softraster

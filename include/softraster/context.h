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
#include <cstdint>
#include <memory>
#include <new>
#include <span>
#include <utility>
#include <vector>

#include "softraster/cache_line_allocator.h"
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
        add(std::make_unique<ClearCommand>(color, depth, stencil));
    }
    // Clears depth only: color and stencil keep what they hold.
    void clear_depth(float depth = 1.0f) { add(std::make_unique<ClearCommand>(depth)); }

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
        recorded_.clear();
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
            add(std::make_unique<GeneralTriangleCommand<S, T>>(shader, state, fb_->samples(), fb_->color_space(), vertices, indices));
            return;
        }
        dispatch_samples(fb_->samples(), [&]<int Samples>() {
            add(std::make_unique<TriangleCommand<S, Samples, T>>(shader, state, vertices, indices));
        });
    }
    // What execute() asks of a command outside its phases, read off it once when it is
    // recorded: the batch's sequential parts then read this array, not the command objects
    // the front end's threads write (whose cache lines would travel from core to core).
    // With more than one thread, each batch's busy tiles are cut into one band of the screen
    // per thread (split_tiles), and a small draw's front end runs, execution after
    // execution, on the thread whose band held most of its tiles the time before
    // (`thread`): what a draw's front end writes is then mostly read back by the same core.
    // (A cache line that moves between the cores takes some 200 ns on the machine we measure
    // on: docs/performance.md.)
    static constexpr uint16_t kAnyThread = 0xffff;
    struct Recorded {
        size_t post_transform_bytes;
        bool small;
        bool uses_stencil;
        uint16_t thread;  // the small draw's front end, or kAnyThread
    };
    void add(std::unique_ptr<Command> command) {
        recorded_.push_back({command->post_transform_bytes(), command->small(), command->uses_stencil(), kAnyThread});
        commands_.push_back(std::move(command));
    }
    // Where a small draw's triangles are, as the thread that binned it wrote it down
    // (Context::execute_batch): the tiles of `range` whose bits `tiles` sets.
    struct Footprint {
        enum class Kind : uint8_t { EveryTile, Tiles, AskCommand } kind = Kind::AskCommand;
        TileRange range;
        uint64_t tiles = 0;  // bit k: local tile k of range
    };
    static Footprint footprint_of(const Command& c);
    // Each tile's commands of a batch in draw order: tile t's are commands[first[t] ..
    // first[t + 1]). Built after binning, so a tile visits only the draws that touch it;
    // `busy` lists the tiles that have any, the back end's work items, and `shares` where each
    // thread's share of them begins (WorkerPool::parallel_for), one past the last's the end.
    struct TileLists {
        std::vector<uint32_t> first;
        std::vector<Command*> commands;
        std::vector<uint32_t> busy;
        std::vector<uint32_t> shares;
    };
    using Commands = std::span<const std::unique_ptr<Command>>;
    void execute_batch(size_t first, size_t size, const DrawTarget& target);  // commands [first, first + size)
    // (`footprints`: the batch's part of footprints_; `lists`: its tile lists, execute_batch;
    // `first`: the batch's first command, whose small draws' threads it votes.)
    void list_commands_by_tile(size_t first, Commands batch, std::span<const Footprint> footprints, const TileGrid& grid, TileLists& lists);
    // With more than one thread, between the listing's passes: the busy tiles' bands
    // (tile_thread_, lists.shares), `everywhere` of the batch's commands drawn in every tile.
    void split_tiles(size_t everywhere, const TileGrid& grid, TileLists& lists);
    // An item of a front-end phase: a small draw, or a chunk of a bigger one. It carries all
    // the thread that takes it reads of the batch's lists, written on the calling thread.
    struct WorkItem {
        uint32_t command;  // its index in the batch
        uint32_t chunk;
        uint16_t thread;  // whose share it goes to
        bool small;
    };
    // Sizes the blocks of post-transform vertices for the batch and places the big draws' in
    // the first; returns the bytes they take there (the small draws' are placed as they run).
    size_t place_post_transform(Commands batch, std::span<const Recorded> recorded, std::span<const WorkItem> items, unsigned threads);

    Framebuffer* fb_;
    WorkerPool* pool_;
    std::vector<uint32_t> owners_;  // per thread: the owner of each sample of its tile
    std::vector<std::unique_ptr<Command>> commands_;
    std::vector<Recorded> recorded_;  // per command
    // With more than one thread, a set per batch of the execution, as footprints_ has a part:
    // the other threads read a batch's lists as they draw its tiles, and lists the next batch
    // rewrote in place would first have to be taken back from their cores (docs/performance.md,
    // "Tile lists apart"). With one, every batch reuses the first set.
    std::vector<TileLists> tile_lists_;
    // With more than one thread, per command as commands_, each batch writing a part of its
    // own: after a batch's front end the calling thread reads all of its footprints
    // (list_commands_by_tile), and a slot the next batch reused would first have to be taken
    // back from the caller's core by the thread that writes it (docs/performance.md,
    // "Footprints apart"). With one, every batch reuses the first slots, still in the cache.
    std::vector<Footprint> footprints_;
    // Where each thread's share of the front end's items begins (as TileLists::shares).
    std::vector<uint32_t> item_shares_;
    std::vector<uint16_t> tile_thread_;  // per tile of the grid: whose share it is in
    uint64_t fragments_shaded_ = 0;
    size_t batches_ = 0;
    // The batch's post-transform vertices (Command::prepare), a block per thread
    // (place_post_transform), each as big as the most it has held.
    std::vector<CacheLineBlock> post_blocks_;
    std::vector<BinMemory> bin_memory_;  // per thread: the batch's bins its front end wrote
};

}  // namespace softraster

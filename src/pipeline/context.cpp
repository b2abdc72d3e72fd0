#include "softraster/context.h"

namespace softraster {
namespace {

// Runs fn(i, thread) for i in [0, count) on the pool, or inline without one.
template <class F>
void for_each_item(WorkerPool* pool, size_t count, F&& fn) {
    if (pool) {
        pool->parallel_for(count, fn);
    } else {
        for (size_t i = 0; i < count; ++i) fn(i, 0u);
    }
}

// The (command, chunk) pairs of one phase, across all commands, so that small draws share
// the threads instead of each taking a turn.
template <class Count>
std::vector<std::pair<Command*, size_t>> work_items(const std::vector<std::unique_ptr<Command>>& commands, Count count) {
    std::vector<std::pair<Command*, size_t>> items;
    for (const auto& c : commands)
        for (size_t i = 0, n = count(*c); i < n; ++i) items.push_back({c.get(), i});
    return items;
}

}  // namespace

std::pair<size_t, bool> Context::hidden_surface_run(size_t first, int tile, const Rect& rect) const {
    // The longest run of commands from `first` that allow hidden-surface removal (at least
    // the first command), and whether it is worth two passes: several draws and enough
    // overdraw in this tile.
    size_t end = first;
    while (end < commands_.size() && end - first < kMaxRunDraws && commands_[end]->allows_hidden_surface_removal() &&
           commands_[end]->triangles_in_tile(tile) < kMaxTileTriangles)
        ++end;
    if (end == first) return {first + 1, false};
    if (end - first < 2) return {end, false};  // one draw: no overdraw between draws to remove
    double area = 0;
    for (size_t c = first; c < end; ++c) area += commands_[c]->covered_area(tile);
    const double tile_area = double(rect.x1 - rect.x0) * double(rect.y1 - rect.y0);
    return {end, area >= kOverdrawForHiddenSurfaceRemoval * tile_area};
}

void Context::execute() {
    Target t;
    t.fb = fb_;
    t.grid = TileGrid(fb_->width(), fb_->height());
    t.planes = ClipPlanes::for_viewport(fb_->width(), fb_->height());
    t.viewport = {fb_->width(), fb_->height()};
    for (auto& c : commands_) c->prepare();

    // The front end. A small draw (one chunk of vertices, one of primitives) is one item:
    // its primitives are binned right after its vertices are processed, while they are still
    // in this core's cache; with many small draws, processing all vertices first would have
    // evicted them. Bigger draws go in two phases, every chunk of a phase in parallel.
    auto is_small = [](const Command& c) { return c.vertex_chunks() <= 1 && c.primitive_chunks() <= 1; };
    const auto vertex_items = work_items(commands_, [&](const Command& c) { return is_small(c) ? size_t(1) : c.vertex_chunks(); });
    for_each_item(pool_, vertex_items.size(), [&](size_t i, unsigned) {
        Command& c = *vertex_items[i].first;
        if (!is_small(c)) return c.process_vertex_chunk(vertex_items[i].second, t);
        if (c.vertex_chunks() == 1) c.process_vertex_chunk(0, t);
        if (c.primitive_chunks() == 1) c.bin_primitive_chunk(0, t);
    });
    const auto bin_items = work_items(commands_, [&](const Command& c) { return is_small(c) ? size_t(0) : c.primitive_chunks(); });
    for_each_item(pool_, bin_items.size(), [&](size_t i, unsigned) { bin_items[i].first->bin_primitive_chunk(bin_items[i].second, t); });
    for (auto& c : commands_) c->finish_binning(t.grid);

    // One thread per tile at a time, every command in order: no locks on the framebuffer.
    const unsigned threads = pool_ ? pool_->size() : 1;
    std::vector<uint64_t> shaded(threads, 0);
    owners_.resize(size_t(threads) * kTileSize * kTileSize * size_t(fb_->samples()));
    for_each_item(pool_, size_t(t.grid.count()), [&](size_t tile, unsigned thread) {
        const Rect rect = t.grid.tile_rect(int(tile));
        uint32_t* owners = owners_.data() + size_t(thread) * kTileSize * kTileSize * size_t(fb_->samples());
        for (size_t c = 0; c < commands_.size();) {
            const auto [end, worth_it] = hidden_surface_run(c, int(tile), rect);
            if (!worth_it) {
                for (; c < end; ++c)
                    if (!commands_[c]->skips_tile(int(tile))) shaded[thread] += commands_[c]->draw_tile(int(tile), rect, t);
                continue;
            }
            std::fill_n(owners, size_t(kTileSize) * kTileSize * size_t(fb_->samples()), kNoOwner);
            for (size_t k = c; k < end; ++k)
                if (!commands_[k]->skips_tile(int(tile))) commands_[k]->visibility_pass(int(tile), rect, t, uint32_t(k - c), owners);
            for (size_t k = c; k < end; ++k)
                if (!commands_[k]->skips_tile(int(tile)))
                    shaded[thread] += commands_[k]->shading_pass(int(tile), rect, t, uint32_t(k - c), owners);
            c = end;
        }
    });
    fragments_shaded_ = 0;
    for (uint64_t s : shaded) fragments_shaded_ += s;
}

}  // namespace softraster

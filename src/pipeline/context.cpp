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

void Context::execute() {
    Target t;
    t.fb = fb_;
    t.grid = TileGrid(fb_->width(), fb_->height());
    t.planes = ClipPlanes::for_viewport(fb_->width(), fb_->height());
    t.viewport = {fb_->width(), fb_->height()};
    for (auto& c : commands_) c->prepare();

    const auto vertex_items = work_items(commands_, [](const Command& c) { return c.vertex_chunks(); });
    for_each_item(pool_, vertex_items.size(), [&](size_t i, unsigned) { vertex_items[i].first->process_vertex_chunk(vertex_items[i].second, t); });
    const auto bin_items = work_items(commands_, [](const Command& c) { return c.primitive_chunks(); });
    for_each_item(pool_, bin_items.size(), [&](size_t i, unsigned) { bin_items[i].first->bin_primitive_chunk(bin_items[i].second, t); });

    // One thread per tile at a time, every command in order: no locks on the framebuffer.
    std::vector<uint64_t> shaded(pool_ ? pool_->size() : 1, 0);
    for_each_item(pool_, size_t(t.grid.count()), [&](size_t tile, unsigned thread) {
        const Rect rect = t.grid.tile_rect(int(tile));
        for (auto& c : commands_) shaded[thread] += c->draw_tile(int(tile), rect, t);
    });
    fragments_shaded_ = 0;
    for (uint64_t s : shaded) fragments_shaded_ += s;
}

}  // namespace softraster

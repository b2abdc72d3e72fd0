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
std::vector<std::pair<Command*, size_t>> work_items(std::span<const std::unique_ptr<Command>> commands, Count count) {
    std::vector<std::pair<Command*, size_t>> items;
    for (const auto& c : commands)
        for (size_t i = 0, n = count(*c); i < n; ++i) items.push_back({c.get(), i});
    return items;
}

}  // namespace

void Context::list_commands_by_tile(Commands batch, const TileGrid& grid) {
    // A counting sort of (tile, command) pairs by tile, commands in draw order: a binned
    // command in the tiles where it has triangles, any other in every tile.
    const auto tiles = size_t(grid.count());
    auto for_each_tile = [&](const Command& c, auto&& f) {
        if (!c.binned()) {
            for (size_t t = 0; t < tiles; ++t) f(t);
            return;
        }
        const TileRange& r = c.tiles();
        for (int ty = r.y0; ty < r.y1; ++ty)
            for (int tx = r.x0; tx < r.x1; ++tx) {
                const int t = grid.tile_index(tx, ty);
                if (c.triangles_in_tile(t) > 0) f(size_t(t));
            }
    };
    tile_first_.assign(tiles + 1, 0);
    for (const auto& c : batch) for_each_tile(*c, [&](size_t t) { ++tile_first_[t + 1]; });
    for (size_t t = 1; t <= tiles; ++t) tile_first_[t] += tile_first_[t - 1];
    tile_commands_.resize(tile_first_[tiles]);
    std::vector<uint32_t> cursor(tile_first_.begin(), tile_first_.end() - 1);
    for (const auto& c : batch) for_each_tile(*c, [&](size_t t) { tile_commands_[cursor[t]++] = c.get(); });
    busy_tiles_.clear();
    for (size_t t = 0; t < tiles; ++t)
        if (tile_first_[t + 1] > tile_first_[t]) busy_tiles_.push_back(uint32_t(t));
}

void Context::execute() {
    DrawTarget target;
    target.fb = fb_;
    target.grid = TileGrid(fb_->width(), fb_->height());
    target.planes = ClipPlanes::for_viewport(fb_->width(), fb_->height());
    target.viewport = {fb_->width(), fb_->height()};
    for (auto& c : commands_)
        if (c->uses_stencil()) fb_->add_stencil();
    // The commands in batches (Context::batching), each through every phase before the next:
    // a tile's commands run in draw order within a batch, and the batches in order.
    fragments_shaded_ = 0;
    batches_ = 0;
    for (size_t begin = 0, end; begin < commands_.size(); begin = end) {
        size_t bytes = 0;
        for (end = begin; end < commands_.size();) {
            bytes += commands_[end++]->post_transform_bytes();
            if (end - begin >= batching.draws && bytes >= batching.bytes) break;
        }
        execute_batch(Commands(commands_).subspan(begin, end - begin), target);
        ++batches_;
    }
}

void Context::execute_batch(Commands batch, const DrawTarget& target) {
    // The batch's post-transform vertices in one block of memory, the same block batch after
    // batch: the vertices the front end writes land on cache lines the tiles have just read.
    auto footprint = [](const Command& c) { return (c.post_transform_bytes() + 63) & ~size_t(63); };  // (64-byte aligned)
    size_t bytes = 0;
    for (auto& c : batch) bytes += footprint(*c);
    if (bytes > post_transform_size_) {
        post_transform_.reset(static_cast<std::byte*>(::operator new(bytes, std::align_val_t(64))));
        post_transform_size_ = bytes;
    }
    bytes = 0;
    for (auto& c : batch) {
        c->prepare(post_transform_.get() + bytes);
        bytes += footprint(*c);
    }

    // The front end. A small draw is one item (Command::process_small): with many small
    // draws, processing all vertices first would have evicted them from the cache before
    // binning. Bigger draws go in two phases, every chunk of a phase in parallel.
    const auto vertex_items = work_items(batch, [&](const Command& c) { return c.small() ? size_t(1) : c.vertex_chunks(); });
    for_each_item(pool_, vertex_items.size(), [&](size_t i, unsigned) {
        Command& c = *vertex_items[i].first;
        if (!c.small()) return c.process_vertex_chunk(vertex_items[i].second, target);
        c.process_small(target);
    });
    const auto bin_items = work_items(batch, [&](const Command& c) { return c.small() ? size_t(0) : c.primitive_chunks(); });
    for_each_item(pool_, bin_items.size(), [&](size_t i, unsigned) { bin_items[i].first->bin_primitive_chunk(bin_items[i].second, target); });
    for (auto& c : batch) c->finish_binning(target.grid);
    list_commands_by_tile(batch, target.grid);

    // The back end: one thread per tile at a time, the tile's commands in draw order, so the
    // framebuffer needs no locks. Runs of opaque draws with heavy overdraw are drawn in two
    // passes (hidden_surface_removal.h); everything else one command after another.
    const unsigned threads = pool_ ? pool_->size() : 1;
    const size_t tile_samples = size_t(kTileSize) * kTileSize * size_t(fb_->samples());
    // Each thread's count on a cache line of its own: counts side by side would bounce their
    // line between the cores at every draw of every tile.
    struct alignas(64) Count {
        uint64_t n = 0;
    };
    std::vector<Count> shaded(threads);
    owners_.resize(size_t(threads) * tile_samples);
    fb_->allow_deferred_clears();
    for_each_item(pool_, busy_tiles_.size(), [&](size_t item, unsigned thread) {
        const size_t tile = busy_tiles_[item];
        const Rect rect = target.grid.tile_rect(int(tile));
        uint32_t* owners = owners_.data() + size_t(thread) * tile_samples;
        const std::span<Command* const> draws(tile_commands_.data() + tile_first_[tile], tile_first_[tile + 1] - tile_first_[tile]);
        uint64_t& count = shaded[thread].n;
        for (size_t c = 0; c < draws.size();) {
            if (!draws[c]->is_clear()) fb_->settle_tile(int(tile));  // (a clear is written before anything draws over it)
            const auto [end, worth_it] = hidden_surface_run(draws, c, int(tile), rect, fb_->samples());
            if (!worth_it) {
                for (; c < end; ++c) count += draws[c]->draw_tile(int(tile), rect, target);
                continue;
            }
            std::fill_n(owners, tile_samples, kNoOwner);
            for (size_t k = c; k < end; ++k) draws[k]->visibility_pass(int(tile), rect, target, uint32_t(k - c), owners);
            for (size_t k = c; k < end; ++k) count += draws[k]->shading_pass(int(tile), rect, target, uint32_t(k - c), owners);
            c = end;
        }
    });
    for (const Count& s : shaded) fragments_shaded_ += s.n;
}

}  // namespace softraster

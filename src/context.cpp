#include "softraster/context.h"

#include <algorithm>

#include "softraster/thread_vote.h"

namespace softraster {
namespace {

// How many small draws a thread claims at a time in the front end's loop
// (WorkerPool::parallel_for's grain), when every item is one: each claim waits for the
// stores of the draws before it, and the draws a thread has claimed are no longer there to
// steal at the loop's end. So about kClaimBytes of post-transform vertices a claim, up to
// kMostClaimed draws: eight of bench_many_draws' cubes, one of bench_many_spheres' spheres
// (docs/performance.md, "A claim per small draw").
constexpr size_t kClaimBytes = size_t(8) << 10;
constexpr size_t kMostClaimed = 8;
size_t small_draws_claimed(size_t draws, size_t bytes) {
    if (draws == 0 || bytes == 0) return 1;
    return std::clamp(kClaimBytes * draws / bytes, size_t(1), kMostClaimed);
}

// A value each thread of a loop changes at every item, on a cache line of its own: values
// side by side would bounce their line between the cores.
template <class T>
struct alignas(kCacheLine) OwnLine {
    T value{};
};

// Stably sorts `items` by the key thread_of(item) < threads (a counting sort), and writes
// where each key's run begins to `shares` (threads + 1 bounds).
template <class T, class Key>
void group_by_thread(std::vector<T>& items, unsigned threads, Key&& thread_of, std::vector<uint32_t>& shares) {
    shares.assign(threads + 1, 0);
    for (const T& item : items) ++shares[thread_of(item) + 1];
    for (unsigned t = 1; t <= threads; ++t) shares[t] += shares[t - 1];
    std::vector<T> sorted(items.size());
    std::vector<uint32_t> cursor(shares.begin(), shares.end() - 1);
    for (const T& item : items) sorted[cursor[thread_of(item)]++] = item;
    items.swap(sorted);
}

// Calls f(tile) for each tile a footprint (Context::Footprint of Kind::Tiles) marks.
template <class Footprint, class F>
void for_each_marked_tile(const Footprint& fp, const TileGrid& grid, F&& f) {
    for (int ty = fp.range.y0, k = 0; ty < fp.range.y1; ++ty)
        for (int tx = fp.range.x0; tx < fp.range.x1; ++tx, ++k)
            if (fp.tiles >> k & 1) f(size_t(grid.tile_index(tx, ty)));
}

}  // namespace

Context::Footprint Context::footprint_of(const Command& c) {
    Footprint f;
    if (!c.binned()) {
        f.kind = Footprint::Kind::EveryTile;
        return f;
    }
    if (c.tiles().count() > 64) return f;  // (Kind::AskCommand)
    f.kind = Footprint::Kind::Tiles;
    f.range = c.tiles();
    f.tiles = c.tiles_with_triangles();
    return f;
}

void Context::list_commands_by_tile(size_t first, Commands batch, std::span<const Footprint> footprints, const TileGrid& grid, TileLists& lists) {
    // A counting sort of (tile, command) pairs by tile, commands in draw order: a binned
    // command in the tiles where it has triangles, any other in every tile. A small draw's
    // tiles come from its footprint, the others' from the command itself.
    const auto tiles = size_t(grid.count());
    auto for_each_tile = [&](size_t i, auto&& f) {
        const Footprint& fp = footprints[i];
        if (fp.kind == Footprint::Kind::Tiles) return for_each_marked_tile(fp, grid, f);
        const Command& c = *batch[i];
        if (fp.kind == Footprint::Kind::EveryTile || !c.binned()) {
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
    std::vector<uint32_t>& starts = lists.first;
    starts.assign(tiles + 1, 0);
    size_t everywhere = 0;  // commands drawn in every tile
    for (size_t i = 0; i < batch.size(); ++i) {
        everywhere += footprints[i].kind == Footprint::Kind::EveryTile;
        for_each_tile(i, [&](size_t t) { ++starts[t + 1]; });
    }
    for (size_t t = 1; t <= tiles; ++t) starts[t] += starts[t - 1];
    lists.busy.clear();
    for (size_t t = 0; t < tiles; ++t)
        if (starts[t + 1] > starts[t]) lists.busy.push_back(uint32_t(t));
    // With more than one thread, the bands are cut between the two passes, so that the second
    // also votes: next time, each small draw's front end runs on the thread of most of its
    // tiles (ties to the first), whose core then reads what it wrote.
    const unsigned threads = pool_ ? pool_->size() : 1;
    if (threads > 1) split_tiles(everywhere, grid, lists);
    ThreadVote vote(threads);
    lists.commands.resize(starts[tiles]);
    std::vector<uint32_t> cursor(starts.begin(), starts.end() - 1);
    for (size_t i = 0; i < batch.size(); ++i) {
        Command* const c = batch[i].get();
        const Footprint& fp = footprints[i];
        if (threads == 1 || fp.kind != Footprint::Kind::Tiles || fp.tiles == 0) {
            for_each_tile(i, [&](size_t t) { lists.commands[cursor[t]++] = c; });
            continue;
        }
        vote.start();
        for_each_marked_tile(fp, grid, [&](size_t t) {
            lists.commands[cursor[t]++] = c;
            vote.add(tile_thread_[t]);
        });
        recorded_[first + i].thread = uint16_t(vote.winner());
    }
}

void Context::split_tiles(size_t everywhere, const TileGrid& grid, TileLists& lists) {
    // The busy tiles in runs of about equal (tile, draw) pairs, one run per thread: bands of
    // the screen, as alike from one execution to the next as the scene. In row order, but
    // column by column where the busy tiles are a strip at least twice as wide as tall (a
    // batch of many small draws far off is often one a few tiles tall: cut along its rows, a
    // fifth of its draws crossed the border; a screen cut into left and right halves drew
    // slower than into top and bottom ones, docs/performance.md).
    // A command drawn in every tile (a clear) counts in neither the weights nor the bounds:
    // it costs a tile next to nothing, and a frame's first batch would otherwise always look
    // like the whole screen.
    const unsigned threads = pool_->size();
    std::vector<uint32_t>& busy = lists.busy;
    auto drawn = [&](uint32_t tile) { return size_t(lists.first[tile + 1] - lists.first[tile]) - everywhere; };
    size_t pairs = 0;
    TileBounds bounds;
    for (uint32_t t : busy)
        if (const size_t d = drawn(t)) pairs += d, bounds.include(grid.tile_x(int(t)), grid.tile_y(int(t)), grid.tile_x(int(t)), grid.tile_y(int(t)));
    if (const TileRange r = bounds.range(); r.x1 - r.x0 >= 2 * (r.y1 - r.y0))  // (busy is in row order: now column by column)
        std::stable_sort(busy.begin(), busy.end(), [&](uint32_t a, uint32_t b) { return grid.tile_x(int(a)) < grid.tile_x(int(b)); });
    const bool only_clears = pairs == 0;  // (then the tiles weigh alike)
    auto weight = [&](uint32_t tile) { return only_clears ? size_t(1) : drawn(tile); };
    const size_t total = only_clears ? busy.size() : pairs;
    lists.shares.assign(threads + 1, uint32_t(busy.size()));
    lists.shares[0] = 0;
    tile_thread_.resize(size_t(grid.count()));
    size_t seen = 0;
    for (unsigned k = 0, t = 0; k < busy.size(); ++k) {
        const uint32_t tile = busy[k];
        tile_thread_[tile] = uint16_t(t);
        seen += weight(tile);
        while (t + 1 < threads && seen * threads >= total * (t + 1)) lists.shares[++t] = k + 1;
    }
}

void Context::execute() {
    DrawTarget target;
    target.fb = fb_;
    target.grid = TileGrid(fb_->width(), fb_->height());
    target.planes = ClipPlanes::for_viewport(fb_->width(), fb_->height());
    target.viewport = {fb_->width(), fb_->height()};
    for (const Recorded& r : recorded_)
        if (r.uses_stencil) fb_->add_stencil();
    // The commands in batches (Context::batching), each through every phase before the next:
    // a tile's commands run in draw order within a batch, and the batches in order.
    fragments_shaded_ = 0;
    batches_ = 0;
    for (size_t begin = 0, end; begin < commands_.size(); begin = end) {
        size_t bytes = 0;
        for (end = begin; end < commands_.size();) {
            bytes += recorded_[end++].post_transform_bytes;
            if (end - begin >= batching.draws && bytes >= batching.bytes) break;
        }
        execute_batch(begin, end - begin, target);
        ++batches_;
    }
}

size_t Context::place_post_transform(Commands batch, std::span<const Recorded> recorded, std::span<const WorkItem> items, unsigned threads) {
    // Each thread's small draws' post-transform vertices in a block of the thread's, one after
    // another in the order it runs them (placed as each runs, execute_batch: a draw another
    // thread stole writes into the thief's block, not among the lines its planned thread is
    // writing), the same block batch after batch: a core writes over lines it wrote itself
    // (and mostly read back itself, Context::list_commands_by_tile). So each block has room for every
    // small draw of the batch. A big draw's, whose chunks every thread writes, go first in
    // the first block, placed here. Each draw's take whole lines (Command::prepare's alignment).
    post_blocks_.resize(threads);
    size_t big = 0, small = 0;
    for (const WorkItem& item : items)
        if (item.chunk == 0) (item.small ? small : big) += whole_cache_lines(recorded[item.command].post_transform_bytes);
    for (unsigned t = 0; t < threads; ++t) {
        const size_t need = (t == 0 ? big : 0) + small;
        if (need > post_blocks_[t].size()) post_blocks_[t] = CacheLineBlock(need);
    }
    size_t at = 0;
    for (const WorkItem& item : items) {
        if (item.chunk != 0 || item.small) continue;
        batch[item.command]->prepare(post_blocks_[0].data() + at);
        at += whole_cache_lines(recorded[item.command].post_transform_bytes);
    }
    return at;
}

void Context::execute_batch(size_t first, size_t size, const DrawTarget& target) {
    const Commands batch = Commands(commands_).subspan(first, size);
    const std::span<const Recorded> recorded = std::span<const Recorded>(recorded_).subspan(first, size);
    // What one thread hands another in a batch, its footprints and its tile lists: with more
    // than one thread, memory of the batch's own (a part of footprints_ per command, a set of
    // tile_lists_ per batch, batches_ being this batch's index in the execution), not written
    // again until the next execution; with one, the first part and set, still in the cache.
    // (Each footprint is written by the thread that runs its draw's front end, or below for
    // big draws: filled in here, on the calling thread, every line would then travel to the
    // core that writes it.)
    const unsigned threads = pool_ ? pool_->size() : 1;
    const size_t at = threads > 1 ? first : 0, set = threads > 1 ? batches_ : 0;
    if (footprints_.size() < at + size) footprints_.resize(at + size);
    if (tile_lists_.size() <= set) tile_lists_.resize(set + 1);
    const std::span<Footprint> footprints = std::span<Footprint>(footprints_).subspan(at, size);
    TileLists& lists = tile_lists_[set];
    // The last batch's tiles are drawn: the bins its front end wrote are free again.
    bin_memory_.resize(threads);
    for (BinMemory& m : bin_memory_) m.reset();

    // The front end. A small draw is one item, all of it on the thread that takes it: its
    // memory placed (Command::prepare), its vertices processed and its primitives binned
    // (Command::process_small: with many small draws, processing all vertices first would
    // have evicted them from the cache before binning), its per-tile totals summed and its
    // footprint written down. Bigger draws go in two phases, every chunk of a phase in
    // parallel, placed before and summed after.
    std::vector<WorkItem> vertex_items, bin_items;
    size_t big_chunks = 0, small_bytes = 0;
    for (size_t i = 0; i < size; ++i) {
        if (recorded[i].small) {
            small_bytes += recorded[i].post_transform_bytes;
            // The thread it went to last time, or at first one of equal runs in draw order.
            const uint16_t thread = recorded[i].thread < threads ? recorded[i].thread : uint16_t(i * threads / size);
            vertex_items.push_back({uint32_t(i), 0, thread, true});
            continue;
        }
        Command& c = *batch[i];
        for (size_t k = 0, n = c.vertex_chunks(); k < n; ++k) vertex_items.push_back({uint32_t(i), uint32_t(k), 0, false}), ++big_chunks;
        for (size_t k = 0, n = c.primitive_chunks(); k < n; ++k) bin_items.push_back({uint32_t(i), uint32_t(k), 0, false});
    }
    // A big draw's chunks in equal runs over the threads.
    for (size_t k = 0, n = 0; k < vertex_items.size(); ++k)
        if (!vertex_items[k].small) vertex_items[k].thread = uint16_t(n++ * threads / big_chunks);
    group_by_thread(vertex_items, threads, [](const WorkItem& item) { return item.thread; }, item_shares_);
    const size_t big_bytes = place_post_transform(batch, recorded, vertex_items, threads);
    // Where each thread's next small draw's vertices go: its block, after the big draws' in
    // the first.
    std::vector<OwnLine<std::byte*>> cursors(threads);
    for (unsigned t = 0; t < threads; ++t) cursors[t].value = post_blocks_[t].data() + (t == 0 ? big_bytes : 0);
    // (The loops' functions hold copies of what they read, not references to this frame's
    // locals: every thread reads them at every index, and what the calling thread writes on
    // its stack while it runs its own items may share their lines: WorkerPool::parallel_for.)
    // (The draw's size from the command, which the item reads anyway, not from recorded_,
    // whose lines the calling thread wrote last.)
    parallel_for(pool_, vertex_items.size(), [batch, target, items = vertex_items.data(), cursors = cursors.data(), footprints = footprints.data(),
                                              bins = bin_memory_.data()](size_t k, unsigned thread) {
        const WorkItem& item = items[k];
        Command& c = *batch[item.command];
        if (!item.small) return c.process_vertex_chunk(item.chunk, target);
        c.prepare(cursors[thread].value);
        cursors[thread].value += whole_cache_lines(c.post_transform_bytes());
        c.process_small(target, bins[thread]);
        c.finish_binning(target.grid);
        footprints[item.command] = footprint_of(c);
    }, item_shares_, big_chunks == 0 ? small_draws_claimed(vertex_items.size(), small_bytes) : 1);
    parallel_for(pool_, bin_items.size(), [batch, target, items = bin_items.data(), bins = bin_memory_.data()](size_t k, unsigned thread) {
        batch[items[k].command]->bin_primitive_chunk(items[k].chunk, target, bins[thread]);
    });
    for (size_t i = 0; i < size; ++i)
        if (!recorded[i].small) {
            batch[i]->finish_binning(target.grid);
            footprints[i] = Footprint{};  // (Kind::AskCommand)
        }
    list_commands_by_tile(first, batch, footprints, target.grid, lists);

    // The back end: one thread per tile at a time, the tile's commands in draw order, so the
    // framebuffer needs no locks. Runs of opaque draws with heavy overdraw are drawn in two
    // passes (hidden_surface_removal.h); everything else one command after another.
    const size_t tile_samples = size_t(kTileSize) * kTileSize * size_t(fb_->samples());
    std::vector<OwnLine<uint64_t>> shaded(threads);  // each thread's count of fragments
    owners_.resize(size_t(threads) * tile_samples);
    fb_->allow_deferred_clears();
    parallel_for(pool_, lists.busy.size(), [this, target, tile_samples, shaded = shaded.data(), busy = lists.busy.data(), tile_first = lists.first.data(),
                                            commands = lists.commands.data()](size_t item, unsigned thread) {
        const size_t tile = busy[item];
        const Rect rect = target.grid.tile_rect(int(tile));
        uint32_t* owners = owners_.data() + size_t(thread) * tile_samples;
        const std::span<Command* const> draws(commands + tile_first[tile], tile_first[tile + 1] - tile_first[tile]);
        uint64_t& count = shaded[thread].value;
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
    }, lists.shares);
    for (const OwnLine<uint64_t>& s : shaded) fragments_shaded_ += s.value;
}

}  // namespace softraster

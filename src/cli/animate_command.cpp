#include <chrono>
#include <condition_variable>
#include <exception>
#include <map>
#include <mutex>
#include <thread>
#include <vector>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "cli/commands.h"
#include "cli/model_options.h"
#include "cli/progress.h"
#include "softraster/error.h"
#include "softraster/io/animation_write.h"
#include "softraster/scene/animation.h"
#include "softraster/scene/scene_renderer.h"

namespace softraster::cli {
namespace {

// Draws frames 0 .. count-1 with `render(k, threads)` and hands them to `write(k, picture)`
// in order. With T threads, T frames are drawn at once on one thread each: a frame's own
// threads wait at its serial parts (setup, binning, the resolve), frames do not wait for
// each other, and the writer (an encoder) runs beside them. At most 2T frames are held. A
// frame is the same picture at any thread count, so the output does not depend on T.
template <class Render, class Write>
void render_in_order(long count, unsigned threads, Render render, Write write) {
    const long lanes = std::min<long>(threads, count);
    if (lanes <= 1) {
        for (long k = 0; k < count; ++k) write(k, render(k, threads));
        return;
    }
    std::mutex mutex;
    std::condition_variable changed;
    std::map<long, Image> done;
    long next = 0, written = 0;
    std::exception_ptr failure;
    auto worker = [&] {
        for (;;) {
            long k;
            {
                std::unique_lock lock(mutex);
                changed.wait(lock, [&] { return failure || next >= count || next < written + 2 * lanes; });
                if (failure || next >= count) return;
                k = next++;
            }
            try {
                Image picture = render(k, 1);
                const std::lock_guard lock(mutex);
                done.emplace(k, std::move(picture));
            } catch (...) {
                const std::lock_guard lock(mutex);
                if (!failure) failure = std::current_exception();
            }
            changed.notify_all();
        }
    };
    std::vector<std::jthread> pool;
    for (long i = 0; i < lanes; ++i) pool.emplace_back(worker);
    try {
        for (long k = 0; k < count; ++k) {
            Image picture;
            {
                std::unique_lock lock(mutex);
                changed.wait(lock, [&] { return failure || done.count(k) > 0; });
                if (failure) std::rethrow_exception(failure);
                picture = std::move(done.at(k));
                done.erase(k);
            }
            write(k, picture);
            {
                const std::lock_guard lock(mutex);
                written = k + 1;
            }
            changed.notify_all();
        }
    } catch (...) {
        {
            const std::lock_guard lock(mutex);
            if (!failure) failure = std::current_exception();
        }
        changed.notify_all();
        pool.clear();  // (the workers see the failure and stop)
        throw;
    }
}

}  // namespace

int run_animate(const AnimateOptions& opt) {
    const std::filesystem::path out = opt.out;
    check_animation_path(out);
    const Scene scene = input_scene(opt.input, opt.model);
    // Keyframes play to their last key; a turntable (asked for, or where nothing moves)
    // turns once.
    const double length = animation_length(scene);
    std::optional<Turntable> turntable;
    if (opt.turntable > 0.0 || length == 0.0) turntable = Turntable{opt.turntable > 0.0 ? opt.turntable : 4.0};
    const double duration = opt.duration > 0.0 ? opt.duration : length > 0.0 ? length : turntable->period;
    const long frames = std::max(1L, std::lround(duration * opt.fps));
    if (frames > 1000000) throw InputError("--duration times --fps gives more than a million frames");
    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<AnimationWriter> writer;
    // The output cannot be written (no room, no permission): the -o flag's error, as
    // render reports it (write_output), not an internal one.
    auto writing = [&](auto&& step) {
        try {
            step();
        } catch (const InputError&) {
            throw;
        } catch (const std::runtime_error& e) {
            throw InputError(e.what());
        }
    };
    Progress progress{size_t(frames), "frames"};
    render_in_order(frames, thread_count(opt.threads), [&](long k, unsigned threads) {
        return SceneRenderer(frame_at(scene, double(k) / opt.fps, turntable), threads).render();
    }, [&](long k, const Image& picture) {
        writing([&] {
            if (!writer) writer = open_animation(out, picture.width, picture.height, opt.fps, scene.color_space);
            writer->add(picture);
        });
        progress.update(size_t(k + 1), "");
    });
    writing([&] { writer->finish(); });
    progress.clear();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "wrote %s (%ld frames, %dx%d, %d fps) in %.1f s\n", out.string().c_str(), frames, scene.width, scene.height,
                 opt.fps, seconds);
    return 0;
}

}  // namespace softraster::cli

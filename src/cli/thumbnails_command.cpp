// softraster thumbnails: a picture of every model file in folders, globs and lists.
//
// Each file is drawn in a child process of its own (fork), several at once. A file that
// crashes or hangs a model importer then costs that file only: the child's death or its
// timeout is reported as the file's failure and the batch goes on. Memory stays bounded by
// the largest models being drawn at once, whatever the number of files.
#include <glob.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/model_options.h"
#include "cli/progress.h"
#include "softraster/error.h"
#include "softraster/io/atomic_write.h"
#include "softraster/io/image_io.h"
#include "softraster/scene/model.h"
#include "softraster/scene/scene_renderer.h"

namespace softraster::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using Clock = std::chrono::steady_clock;

struct Item {
    std::string input;   // as found (the argument, or a path under it)
    fs::path output;     // empty when the input could not be used at all
    json result;         // {"status": "ok" | "failed" | "skipped", ...}
};

bool has_wildcard(const std::string& s) { return s.find_first_of("*?[") != std::string::npos; }

// The output for `file` found under `base`: the same relative path under `out`, with ".png"
// added to the whole file name (so a.obj and a.fbx do not collide). Files named one by one
// mirror the deepest folder they share.
fs::path output_for(const fs::path& file, const fs::path& base, const fs::path& out) {
    const fs::path rel = base.empty() ? file.filename() : file.lexically_relative(base);
    return out / rel.parent_path() / (rel.filename().string() + ".png");
}

void add_folder(const fs::path& dir, const fs::path& out, std::vector<Item>& items) {
    std::vector<fs::path> files;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(dir, fs::directory_options::skip_permission_denied, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (it->is_regular_file(ec) && is_model_file(it->path())) files.push_back(it->path());
    }
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) items.push_back({f.string(), output_for(f, dir, out), json()});
}

// A glob's matches, each placed under `out` relative to the pattern's folders that have no
// wildcard ("models/*/x.glb" -> out/<dir>/x.glb.png).
void add_glob(const std::string& pattern, const fs::path& out, std::vector<Item>& items) {
    fs::path base;
    for (const fs::path& part : fs::path(pattern).parent_path()) {
        if (has_wildcard(part.string())) break;
        base /= part;
    }
    glob_t g{};
    if (glob(pattern.c_str(), 0, nullptr, &g) == 0) {
        for (size_t i = 0; i < g.gl_pathc; ++i) {
            const fs::path p = g.gl_pathv[i];
            std::error_code ec;
            if (fs::is_directory(p, ec)) add_folder(p, out / p.lexically_relative(base.empty() ? "." : base), items);
            else items.push_back({p.string(), output_for(p, base, out), json()});
        }
    } else {
        items.push_back({pattern, {}, {{"status", "failed"}, {"reason", "no file matches"}}});
    }
    globfree(&g);
}

// The deepest folder that holds all the files (for mirroring several files named one by one).
fs::path common_folder(const std::vector<fs::path>& files) {
    if (files.size() < 2) return {};
    fs::path common = files[0].parent_path();
    for (const fs::path& f : files) {
        const fs::path dir = f.parent_path();
        fs::path shared;
        for (auto a = common.begin(), b = dir.begin(); a != common.end() && b != dir.end() && *a == *b; ++a, ++b) shared /= *a;
        common = shared;
    }
    return common;
}

std::vector<Item> collect(const std::vector<std::string>& inputs, const fs::path& out) {
    std::vector<Item> items;
    std::vector<fs::path> named;  // files named one by one
    std::error_code ec;
    for (const std::string& in : inputs)
        if (!fs::is_directory(in, ec) && fs::exists(in, ec)) named.push_back(fs::absolute(in).lexically_normal());
    const fs::path named_base = common_folder(named);
    for (const std::string& in : inputs) {
        if (fs::is_directory(in, ec)) add_folder(in, out, items);
        else if (fs::exists(in, ec))
            items.push_back({in, output_for(named_base.empty() ? fs::path(in) : fs::absolute(in).lexically_normal(), named_base, out), json()});
        else if (has_wildcard(in)) add_glob(in, out, items);
        else items.push_back({in, {}, {{"status", "failed"}, {"reason", "file not found"}}});
    }
    // Two inputs with one output (the same file named twice, or a.obj given from two folders).
    std::map<fs::path, std::string> taken;
    for (Item& item : items) {
        if (item.output.empty()) continue;
        const auto [at, fresh] = taken.emplace(item.output.lexically_normal(), item.input);
        if (!fresh) {
            item.result = {{"status", "failed"}, {"reason", "same output as " + at->second}};
            item.output.clear();
        }
    }
    return items;
}

// Caps the child's address space so a file that makes an importer allocate without end
// fails alone and fast (std::bad_alloc) instead of driving the machine into swap. Not under
// AddressSanitizer, which reserves terabytes of address space for its shadow memory.
void limit_memory(size_t megabytes) {
#if defined(__SANITIZE_ADDRESS__)
    (void)megabytes;
#else
    const rlim_t bytes = rlim_t(megabytes) << 20;
    const rlimit limit{bytes, bytes};
    setrlimit(RLIMIT_AS, &limit);
#endif
}

// In the child: draw one model, write its picture, send the result as one JSON line.
[[noreturn]] void draw_in_child(const Item& item, const ModelPicture& picture, unsigned threads, size_t max_mb, int fd) {
    limit_memory(max_mb);
    json r;
    {
        const auto start = Clock::now();
        try {
            const Model model = load_model(item.input, MissingTexture::Warn, picture.color_space);
            const Scene scene = model_scene(model, picture);
            const SceneRenderer renderer(scene, threads);
            const Image image = renderer.render();
            std::error_code ec;
            fs::create_directories(item.output.parent_path(), ec);
            write_png(image, item.output);
            r = {{"status", "ok"}, {"warnings", model.warnings}, {"ignored", model.ignored},
                 {"triangles", renderer.triangle_count()}};
        } catch (const InputError& e) {
            r = {{"status", "failed"}, {"reason", e.what()}};
        } catch (const std::bad_alloc&) {
            r = {{"status", "failed"}, {"reason", "out of memory (more than " + std::to_string(max_mb) + " MB; see --max-memory)"}};
        } catch (const std::exception& e) {
            r = {{"status", "failed"}, {"reason", std::string("internal error: ") + e.what()}};
        }
        r["ms"] = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        const std::string line = r.dump(-1, ' ', false, json::error_handler_t::replace) + "\n";
        for (size_t sent = 0; sent < line.size();) {
            const ssize_t n = write(fd, line.data() + sent, line.size() - sent);
            if (n <= 0 && errno != EINTR) break;
            if (n > 0) sent += size_t(n);
        }
    }
    std::exit(0);  // (exit, not _exit: the sanitizers' leak check runs in children too)
}

struct Child {
    size_t item;
    int fd;
    std::string received;
    Clock::time_point start;
    bool timed_out = false;
};

// The result of a child that has ended: its JSON line, or why there is none.
json child_result(const Child& c, int status, int timeout_s) {
    if (c.timed_out) return {{"status", "failed"}, {"reason", "timed out after " + std::to_string(timeout_s) + " s"}};
    try {
        json r = json::parse(c.received);
        if (r.is_object() && r.contains("status")) return r;
    } catch (const json::exception&) {
    }
    if (WIFSIGNALED(status))
        return {{"status", "failed"},
                {"reason", "crashed (signal " + std::to_string(WTERMSIG(status)) + ", " + strsignal(WTERMSIG(status)) + ")"}};
    return {{"status", "failed"}, {"reason", "ended without a result (exit status " + std::to_string(WEXITSTATUS(status)) + ")"}};
}

std::string short_reason(const Item& item) {
    std::string reason = item.result.value("reason", "");
    // Errors name the input file first; it is already on the line.
    if (reason.rfind(item.input + ": ", 0) == 0) reason = reason.substr(item.input.size() + 2);
    return reason;
}

}  // namespace

int run_thumbnails(const ThumbnailsOptions& opt) {
    const ModelPicture picture = opt.model.picture(256);
    const fs::path out = opt.out;
    std::error_code ec;
    fs::create_directories(out, ec);
    if (!fs::is_directory(out, ec)) throw InputError(out.string() + ": cannot create the output folder");
    std::vector<Item> items = collect(opt.inputs, out);
    if (items.empty()) throw InputError("no model files found in the inputs");

    const unsigned cores = thread_count(0);
    const size_t jobs = std::min<size_t>(opt.jobs > 0 ? size_t(opt.jobs) : cores, items.size());
    const unsigned threads = std::max(1u, cores / unsigned(jobs));  // (a few large models: threads inside each)
    Progress progress(items.size());
    size_t done = 0, failed = 0, skipped = 0;
    const auto start = Clock::now();
    auto finish = [&](Item& item) {
        ++done;
        const std::string status = item.result.value("status", "failed");
        if (status == "failed") ++failed;
        if (status == "skipped") ++skipped;
        progress.clear();
        if (status == "failed") {
            std::fprintf(stderr, "failed  %s: %s\n", item.input.c_str(), short_reason(item).c_str());
        } else if (!opt.quiet && !progress.on_terminal()) {
            std::fprintf(stderr, "%-7s %s -> %s\n", status.c_str(), item.input.c_str(), item.output.string().c_str());
        }
        if (status == "ok" && item.result.contains("warnings"))
            for (const auto& w : item.result["warnings"]) std::fprintf(stderr, "warning %s\n", w.get<std::string>().c_str());
        if (status == "ok" && opt.model.verbose && item.result.contains("ignored"))
            for (const auto& what : item.result["ignored"])
                std::fprintf(stderr, "%s: not drawn: %s\n", item.input.c_str(), what.get<std::string>().c_str());
        if (!opt.quiet) progress.update(done, failed ? std::to_string(failed) + " failed" : "", true);
    };

    std::map<pid_t, Child> running;
    size_t next = 0;
    while (next < items.size() || !running.empty()) {
        while (running.size() < jobs && next < items.size()) {
            Item& item = items[next];
            const size_t index = next++;
            if (!item.result.is_null()) {
                finish(item);
                continue;
            }
            if (opt.skip_existing && fs::exists(item.output, ec)) {
                item.result = {{"status", "skipped"}, {"reason", "picture exists"}};
                finish(item);
                continue;
            }
            int fds[2];
            if (pipe(fds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
            std::fflush(nullptr);
            const pid_t pid = fork();
            if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
            if (pid == 0) {
                close(fds[0]);
                for (const auto& [other, c] : running) close(c.fd);
                draw_in_child(item, picture, threads, size_t(opt.max_memory), fds[1]);
            }
            close(fds[1]);
            running.emplace(pid, Child{index, fds[0], {}, Clock::now()});
        }
        if (running.empty()) continue;
        std::vector<pollfd> polls;
        std::vector<pid_t> pids;
        for (auto& [pid, c] : running) {
            polls.push_back({c.fd, POLLIN, 0});
            pids.push_back(pid);
        }
        poll(polls.data(), polls.size(), 100);
        for (size_t i = 0; i < polls.size(); ++i) {
            Child& c = running.at(pids[i]);
            bool ended = false;
            if (polls[i].revents & (POLLIN | POLLHUP | POLLERR)) {
                char buf[4096];
                const ssize_t n = read(c.fd, buf, sizeof buf);
                if (n > 0) c.received.append(buf, size_t(n));
                else if (n == 0 || errno != EINTR) ended = true;
            }
            if (!ended && !c.timed_out && Clock::now() - c.start > std::chrono::seconds(opt.timeout)) {
                c.timed_out = true;
                kill(pids[i], SIGKILL);
            }
            if (!ended) continue;
            int status = 0;
            while (waitpid(pids[i], &status, 0) < 0 && errno == EINTR) {
            }
            close(c.fd);
            Item& item = items[c.item];
            item.result = child_result(c, status, opt.timeout);
            running.erase(pids[i]);
            finish(item);
        }
        if (!opt.quiet) progress.update(done, failed ? std::to_string(failed) + " failed" : "");
    }
    progress.clear();

    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    const size_t drawn = items.size() - failed - skipped;
    json report = {{"summary",
                    {{"files", items.size()}, {"ok", drawn}, {"failed", failed}, {"skipped", skipped},
                     {"seconds", seconds}, {"files_per_second", seconds > 0 ? double(drawn) / seconds : 0.0}}},
                   {"inputs", json::array()}};
    for (const Item& item : items) {
        json entry = item.result;
        entry["input"] = item.input;
        if (!item.output.empty()) entry["output"] = item.output.string();
        report["inputs"].push_back(entry);
    }
    const fs::path report_path = opt.report.empty() ? out / "thumbnails.json" : fs::path(opt.report);
    const std::string text = report.dump(1, ' ', false, json::error_handler_t::replace) + "\n";
    try {
        write_file_atomically(report_path, text);
    } catch (const std::runtime_error& e) {
        std::fprintf(stderr, "softraster: error: cannot write the report: %s\n", e.what());
    }
    std::fprintf(stderr, "%zu files: %zu drawn, %zu failed, %zu skipped in %.1f s (%.1f files/s); report: %s\n",
                 items.size(), drawn, failed, skipped, seconds, seconds > 0 ? double(drawn) / seconds : 0.0,
                 report_path.string().c_str());
    return failed > 0 ? 1 : 0;
}

}  // namespace softraster::cli

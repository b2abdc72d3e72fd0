// softraster view: a scene or model in a window, turned with the mouse and keys, redrawn
// with all cores; the file reloads when it changes.
//
// Double buffering, as the book this project grows from builds it: the renderer draws the
// next frame into the back buffer while the window keeps showing the front one; when the
// frame is complete the two swap and the window presents the new front. The window (SDL)
// only presents pixels; src/platform/window.h.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "cli/commands.h"
#include "cli/model_options.h"
#include "platform/terminal.h"
#include "platform/window.h"
#include "softraster/error.h"
#include "softraster/io/image_write.h"
#include "softraster/scene/animation.h"
#include "softraster/scene/scene_renderer.h"

namespace softraster::cli {
namespace {

constexpr Shading kShadings[] = {Shading::Lambert, Shading::BlinnPhong, Shading::Phong, Shading::Pbr, Shading::Unlit,
                                 Shading::Flat,    Shading::Gouraud,    Shading::Normals};
constexpr const char* kShadingNames[] = {"lambert", "blinn_phong", "phong", "pbr", "unlit", "flat", "gouraud", "normals"};
constexpr const char* kFilterNames[] = {"nearest", "bilinear", "trilinear"};
constexpr double kKeyStep = 15.0;  // degrees per arrow key: k presses = render --turntable 24 --time k

// What the user has changed, applied to the loaded scene for each frame.
struct View {
    double azimuth = 0.0, elevation = 0.0;  // degrees: the turntable, and the camera's height
    float zoom = 1.0f;
    glm::vec2 pan{0.0f};                     // in units of the distance to the target
    int shading = -1, filter = -1;           // indices into the tables above, -1: the file's own
    bool wireframe = false, depth = false, no_cull = false;
    std::optional<int> samples;
    int width = 0, height = 0;               // 0: the scene's size
    double time = 0.0;                       // seconds into the keyframes, which play unless paused
    bool paused = false;
};

Scene frame_scene(const Scene& loaded, const View& v) {
    Scene s = turned_scene(scene_at(loaded, v.time), v.azimuth);
    if (v.width > 0) s.width = v.width, s.height = v.height;
    if (v.samples) s.samples = *v.samples;
    Camera& c = s.camera;
    const glm::vec3 up = glm::normalize(c.up);
    glm::vec3 offset = c.eye - c.target;
    const glm::vec3 right = glm::normalize(glm::cross(-offset, up));
    if (v.elevation != 0.0) {  // about the camera's right axis, through the target (Rodrigues)
        const float a = float(glm::radians(v.elevation));
        offset = offset * std::cos(a) + glm::cross(right, offset) * std::sin(a) + right * glm::dot(right, offset) * (1.0f - std::cos(a));
    }
    offset /= v.zoom;
    if (c.orthographic) c.height /= v.zoom;
    const float distance = glm::length(offset);
    const glm::vec3 view_up = glm::normalize(glm::cross(right, -offset));
    const glm::vec3 shift = (right * v.pan.x + view_up * v.pan.y) * distance;
    c.target += shift;
    c.eye = c.target + offset;
    for (SceneObject& o : s.objects) {
        if (v.depth) o.material.shading = Shading::Depth;
        else if (v.shading >= 0) o.material.shading = kShadings[v.shading];
        if (v.wireframe && o.primitive == Topology::Triangles) o.wireframe = Wireframe{};
        if (v.no_cull) o.cull = CullMode::None;
        if (v.filter >= 0) {
            o.material.sampler.mag = o.material.sampler.min = v.filter == 0 ? Filter::Nearest : Filter::Bilinear;
            o.material.sampler.mip = v.filter == 2 ? MipFilter::Linear : MipFilter::None;
        }
    }
    return s;
}

std::string status_line(const Scene& s, const View& v, double ms, size_t triangles, bool animated) {
    char text[512], clock[64] = "";
    if (animated) std::snprintf(clock, sizeof clock, "  t %.2f s%s", v.time, v.paused ? " (paused)" : "");
    std::snprintf(text, sizeof text, "%.1f ms  %.0f fps  %zu tris  %dx%d  %s  msaa %dx  cull %s  filter %s%s%s", ms, ms > 0 ? 1000.0 / ms : 0.0,
                  triangles, s.width, s.height, v.depth ? "depth" : (v.shading >= 0 ? kShadingNames[v.shading] : "file's shading"), s.samples,
                  v.no_cull ? "none" : "file", v.filter >= 0 ? kFilterNames[v.filter] : "file", v.wireframe ? "  wireframe" : "", clock);
    return text;
}

std::filesystem::file_time_type modified(const std::filesystem::path& p) {
    std::error_code ec;
    const auto t = std::filesystem::last_write_time(p, ec);
    return ec ? std::filesystem::file_time_type{} : t;
}

// The viewer's loop, on a window (platform/window.h) or the terminal (platform/terminal.h).
template <class Display>
int view_loop(Display& display, Scene loaded, const ViewOptions& options) {
    const std::filesystem::path path = options.input;
    auto stamp = modified(path);
    View view;
    Image front, back;  // the display shows front; the next frame is drawn into back
    std::string error, status;
    int screenshot = 0;
    bool dirty = true, quit = false;
    double length = animation_length(loaded);  // of the keyframes (0: nothing moves), again after each reload
    std::optional<Framebuffer> fb;  // kept from frame to frame while its size and format stay
    auto draw = [&] {
        const Scene scene = frame_scene(loaded, view);
        const SceneRenderer renderer(scene, thread_count(options.threads));
        const auto start = std::chrono::steady_clock::now();
        if (!fb || !renderer.fits(*fb)) fb.emplace(renderer.make_framebuffer());
        renderer.render(*fb);
        back = renderer.resolve(*fb);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        std::swap(front, back);  // the frame is complete: it becomes the one shown
        status = status_line(scene, view, ms, renderer.triangle_count(), length > 0.0);
        display.present(front, status, error);
        dirty = false;
    };
    auto last_frame = std::chrono::steady_clock::now();
    const auto first_frame = last_frame;
    int frames = 0;
    while (!quit) {
        if (options.orbit_frames > 0) {  // the measured orbit: every frame turned a step further
            if (frames == options.orbit_frames) {
                const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - first_frame).count();
                std::printf("%d frames in %.3f s: %.2f frames/s\n", frames, s, frames / s);
                break;
            }
            view.azimuth = 360.0 * frames / options.orbit_frames;
            dirty = true;
        }
        // Keyframes play in real time, looping.
        const auto now = std::chrono::steady_clock::now();
        if (length > 0.0 && !view.paused) {
            view.time = std::fmod(view.time + std::chrono::duration<double>(now - last_frame).count(), length);
            dirty = true;
        }
        last_frame = now;
        if (dirty) draw(), ++frames;
        for (const platform::InputEvent& e : display.events((length > 0.0 && !view.paused) || options.orbit_frames > 0 ? 0 : 250)) {
            using Kind = platform::InputEvent::Kind;
            if (e.kind != Kind::Key || (e.key != 'p' && e.key != platform::kKeyF12)) dirty = true;
            if (e.kind == Kind::Quit) quit = true;
            if (e.kind == Kind::Resize) view.width = e.width, view.height = e.height;
            if (e.kind == Kind::Wheel) view.zoom *= std::pow(1.1f, e.dy);
            if (e.kind == Kind::Drag && e.button == 1) {
                view.azimuth += 0.5 * e.dx;
                view.elevation = std::clamp(view.elevation + 0.5 * e.dy, -85.0, 85.0);
            }
            if (e.kind == Kind::Drag && e.button == 3) view.pan += glm::vec2(-e.dx, e.dy) * 0.002f;
            if (e.kind != Kind::Key) continue;
            switch (e.key) {
                case platform::kKeyLeft: view.azimuth -= kKeyStep; break;
                case platform::kKeyRight: view.azimuth += kKeyStep; break;
                case platform::kKeyUp: view.elevation = std::min(view.elevation + kKeyStep, 85.0); break;
                case platform::kKeyDown: view.elevation = std::max(view.elevation - kKeyStep, -85.0); break;
                case 'r': view.azimuth = view.elevation = 0.0, view.zoom = 1.0f, view.pan = glm::vec2(0.0f); break;
                case 's': view.shading = (view.shading + 1) % int(std::size(kShadings)); break;
                case 'w': view.wireframe = !view.wireframe; break;
                case 'm': view.samples = view.samples.value_or(loaded.samples) > 1 ? 1 : 4; break;
                case 'c': view.no_cull = !view.no_cull; break;
                case 'd': view.depth = !view.depth; break;
                case 'f': view.filter = view.filter == 2 ? -1 : view.filter + 1; break;
                case ' ': view.paused = !view.paused; break;
                case 'q':
                case platform::kKeyEscape: quit = true; break;
                case 'p':
                case platform::kKeyF12: {
                    if (dirty) draw();  // the frame of every input before this key
                    char name[64];
                    std::snprintf(name, sizeof name, "softraster-view-%03d.png", screenshot++);
                    const std::filesystem::path shot = std::filesystem::path(options.screenshots) / name;
                    write_picture(front, shot, loaded.color_space);  // the exact frame shown, without the status line
                    std::fprintf(stderr, "wrote %s (%dx%d)\n", shot.string().c_str(), front.width, front.height);
                    break;
                }
                default: break;
            }
        }
        if (const auto changed = modified(path); changed != stamp) {  // reload; keep the last good scene on an error
            stamp = changed;
            try {
                loaded = input_scene(path, options.model);
                length = animation_length(loaded);
                error.clear();
            } catch (const InputError& e) {
                error = e.what();
            }
            dirty = true;
        }
    }
    return 0;
}

}  // namespace

int run_view(const ViewOptions& opt) {
    const std::filesystem::path path = opt.input;
    Scene loaded = input_scene(path, opt.model);
    if (opt.terminal) {
        platform::Terminal terminal;
        return view_loop(terminal, std::move(loaded), opt);
    }
    platform::Window window("softraster view: " + path.filename().string(), loaded.width, loaded.height);
    return view_loop(window, std::move(loaded), opt);
}

}  // namespace softraster::cli

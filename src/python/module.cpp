// The Python module `softraster` (its compiled part, softraster._softraster): scenes and model
// files to NumPy arrays. Pictures are H x W x 4 uint8 (RGBA, row 0 at the top); the GIL is
// released while a picture is drawn, so N Python threads drawing N pictures use N cores.
// Bad input raises ValueError with the command line's one-line message; a missing file,
// FileNotFoundError. (An importer that crashes takes the process with it: batches of
// untrusted files belong in child processes, as `softraster thumbnails` draws them.)
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "cli/model_options.h"
#include "softraster/error.h"
#include "softraster/io/image_io.h"
#include "softraster/pipeline/resolve.h"
#include "softraster/scene/model.h"
#include "softraster/scene/scene.h"
#include "softraster/scene/scene_renderer.h"
#include "softraster/scene/surface_ids.h"
#include "softraster/srgb.h"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace softraster::python {
namespace {

unsigned threads_of(int threads) {
    if (threads < 0) throw InputError("threads " + std::to_string(threads) + ": expected 0 (one per core) or more");
    return threads > 0 ? unsigned(threads) : std::max(1u, std::thread::hardware_concurrency());
}

py::array_t<uint8_t> color_array(const Image& image) {
    py::array_t<uint8_t> out({image.height, image.width, 4});
    std::memcpy(out.mutable_data(), image.pixels.data(), image.pixels.size() * sizeof(Rgba8));
    return out;
}

// Throws FileNotFoundError for a path that does not exist (ValueError is for what is in it).
void require_file(const fs::path& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) {
        PyErr_SetFromErrnoWithFilename(PyExc_FileNotFoundError, path.string().c_str());
        throw py::error_already_set();
    }
}

// A scene given as a dict, a JSON string or a path.
Scene scene_of(const py::object& scene) {
    if (py::isinstance<py::dict>(scene)) {
        const std::string text = py::module_::import("json").attr("dumps")(scene).cast<std::string>();
        return parse_scene(text, fs::current_path(), "<scene dict>");
    }
    if (py::isinstance<py::str>(scene)) {
        const std::string text = scene.cast<std::string>();
        const size_t first = text.find_first_not_of(" \t\r\n");
        if (first != std::string::npos && text[first] == '{') return parse_scene(text, fs::current_path(), "<scene string>");
    }
    const fs::path path = py::module_::import("os").attr("fspath")(scene).cast<std::string>();
    require_file(path);
    return load_scene(path);
}

// The model options as keyword arguments, checked as the command line checks them.
cli::ModelOptions model_options(const py::object& size, const std::string& view, int samples, const std::optional<std::string>& shading,
                                const std::optional<std::string>& background, const std::string& color_space,
                                const std::string& tone_mapping, float exposure, bool shadows, bool ssao) {
    cli::ModelOptions o;
    if (py::isinstance<py::int_>(size)) {
        o.size = std::to_string(size.cast<int>());
    } else {
        std::pair<int, int> wh;
        try {
            wh = size.cast<std::pair<int, int>>();
        } catch (const py::cast_error&) {
            throw InputError("size " + py::repr(size).cast<std::string>() + ": expected N or (width, height)");
        }
        o.size = std::to_string(wh.first) + "x" + std::to_string(wh.second);
    }
    auto one_of = [](const std::string& what, const std::string& value, std::initializer_list<const char*> allowed) {
        for (const char* a : allowed)
            if (value == a) return;
        std::string list;
        for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
        throw InputError(what + " " + value + ": expected one of " + list);
    };
    o.view = view;  // (view and shading: checked by ModelOptions::picture)
    if (samples != 1 && samples != 2 && samples != 4 && samples != 8 && samples != 16)
        throw InputError("samples " + std::to_string(samples) + ": expected 1, 2, 4, 8 or 16");
    o.samples = samples;
    if (shading) o.shading = *shading;
    if (background) o.background = *background;
    one_of("color_space", color_space, {"srgb", "linear"});
    o.color_space = color_space;
    one_of("tone_mapping", tone_mapping, {"none", "reinhard", "aces"});
    o.tone_mapping = tone_mapping;
    if (!(exposure > 0.0f)) throw InputError("exposure: expected a positive number");
    o.exposure = exposure;
    o.shadows = shadows;
    o.ambient_occlusion = ssao;
    return o;
}

// The camera of a picture: intrinsics K (pixels, origin at the top-left corner of the top-left
// pixel, x right, y down) and world-to-camera matrices in OpenGL's convention (camera looks
// down -z, y up) and OpenCV's (looks down +z, y down): x_cv = diag(1, -1, -1, 1) x_gl.
py::dict camera_of(const Scene& scene) {
    const Camera& c = scene.camera;
    py::dict d;
    d["K"] = py::array(py::cast(camera_intrinsics(c, scene.width, scene.height)));
    d["world_to_camera"] = py::array(py::cast(world_to_camera_cv(c)));
    d["world_to_camera_gl"] = py::array(py::cast(world_to_camera_gl(c)));
    d["width"] = scene.width, d["height"] = scene.height;
    d["near"] = c.near, d["far"] = c.far, d["orthographic"] = c.orthographic;
    return d;
}

// What a call returns besides the color picture (each documented in help(softraster)).
struct Outputs {
    bool depth = false;
    std::optional<NormalSpace> normals;
    bool ids = false;
    bool linear = false;
    bool any() const { return depth || normals || ids || linear; }
};
Outputs outputs_of(bool depth, const std::optional<std::string>& normals, bool ids, bool linear) {
    Outputs o{depth, std::nullopt, ids, linear};
    if (normals) {
        if (*normals != "world" && *normals != "camera") throw InputError("normals " + *normals + ": expected world or camera");
        o.normals = *normals == "world" ? NormalSpace::World : NormalSpace::Camera;
    }
    return o;
}

struct Rendered {
    Image color;
    GrayImage<float> depth;
    SurfaceIds ids;
    std::vector<glm::vec3> normals;
    double ms = 0.0;  // drawing it: the renderer's setup, the frame, the resolve and the extra outputs
};
// Draws the scene (and its ids, for ids or normals) with the GIL released.
Rendered draw(const Scene& scene, int threads, const Outputs& want) {
    py::gil_scoped_release unlocked;
    const auto start = std::chrono::steady_clock::now();
    const SceneRenderer renderer(scene, threads_of(threads));
    Framebuffer fb = renderer.make_framebuffer();
    renderer.render(fb);
    Rendered r{renderer.resolve(fb), {}, {}, {}};
    if (want.depth) r.depth = depth_picture(fb);
    if (want.ids || want.normals) r.ids = surface_ids(scene, threads_of(threads));
    if (want.normals) r.normals = surface_normals(scene, r.ids, *want.normals);
    r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return r;
}

py::dict outputs(const Scene& scene, const Rendered& r, const Outputs& want, ColorSpace color_space) {
    py::dict d;
    d["color"] = color_array(r.color);
    const ssize_t h = r.color.height, w = r.color.width;
    if (want.depth) {
        if (r.depth.width != r.color.width)
            throw InputError("depth: not available for supersampled scenes");
        py::array_t<float> z({h, w}), distance({h, w});
        float* zp = z.mutable_data();
        float* dp = distance.mutable_data();
        for (size_t i = 0; i < r.depth.values.size(); ++i) zp[i] = r.depth.values[i], dp[i] = view_distance(r.depth.values[i], scene.camera);
        d["depth"] = distance;
        d["window_z"] = z;
    }
    if (want.normals) {
        py::array_t<float> n({h, w, ssize_t(3)});
        std::memcpy(n.mutable_data(), r.normals.data(), r.normals.size() * sizeof(glm::vec3));
        d["normals"] = n;
    }
    if (want.ids) {
        py::array_t<int32_t> object({h, w}), triangle({h, w});
        std::memcpy(object.mutable_data(), r.ids.object.data(), r.ids.object.size() * sizeof(int32_t));
        std::memcpy(triangle.mutable_data(), r.ids.triangle.data(), r.ids.triangle.size() * sizeof(int32_t));
        d["object_id"] = object;
        d["triangle_id"] = triangle;
    }
    if (want.linear) {  // the picture's values as linear light: decoded from sRGB, or c / 255
        py::array_t<float> linear({h, w, ssize_t(4)});
        float* out = linear.mutable_data();
        for (size_t p = 0; p < r.color.pixels.size(); ++p) {
            const Rgba8 c = r.color.pixels[p];
            const uint8_t rgb[3] = {c.r, c.g, c.b};
            for (size_t k = 0; k < 3; ++k) out[4 * p + k] = color_space == ColorSpace::Srgb ? srgb::decode(rgb[k]) : rgb[k] / 255.0f;
            out[4 * p + 3] = c.a / 255.0f;
        }
        d["linear"] = linear;
    }
    d["camera"] = camera_of(scene);
    d["draw_ms"] = r.ms;
    return d;
}

class PyModel {
public:
    PyModel(const py::object& path, const std::string& color_space) {
        path_ = py::module_::import("os").attr("fspath")(path).cast<std::string>();
        require_file(path_);
        color_ = color_space == "linear" ? ColorSpace::Linear : ColorSpace::Srgb;
        if (color_space != "srgb" && color_space != "linear") throw InputError("color_space " + color_space + ": expected srgb or linear");
        py::gil_scoped_release unlocked;
        model_ = load_model(path_, MissingTexture::Warn, color_);
    }
    py::dict render(const py::object& size, const std::string& view, int samples, const std::optional<std::string>& shading,
                    const std::optional<std::string>& background, const std::string& tone_mapping, float exposure, bool shadows,
                    bool ssao, bool depth, const std::optional<std::string>& normals, bool ids, bool linear, int threads,
                    const std::optional<std::array<float, 3>>& direction) const {
        const Outputs want = outputs_of(depth, normals, ids, linear);
        const cli::ModelOptions o = model_options(size, view, samples, shading, background,
                                                  color_ == ColorSpace::Linear ? "linear" : "srgb", tone_mapping, exposure, shadows, ssao);
        ModelPicture picture = o.picture(512);
        if (direction) {
            const glm::vec3 d((*direction)[0], (*direction)[1], (*direction)[2]);
            if (!(glm::dot(d, d) > 0.0f) || !std::isfinite(glm::dot(d, d))) throw InputError("direction: expected a nonzero finite vector");
            picture.to_eye = d;
        }
        const Scene scene = model_scene(model_, picture);
        return outputs(scene, draw(scene, threads, want), want, scene.color_space);
    }
    // Object i's triangles in world space (its node's transform applied), as drawn.
    py::dict mesh(ssize_t i) const {
        if (i < 0 || size_t(i) >= model_.objects.size())
            throw py::index_error("object " + std::to_string(i) + ": the model has " + std::to_string(model_.objects.size()));
        const SceneObject& o = model_.objects[size_t(i)];
        const Mesh& mesh = *o.mesh;
        const ssize_t v = ssize_t(mesh.vertices.size()), t = ssize_t(mesh.triangle_count());
        py::array_t<float> positions({v, ssize_t(3)}), normals({v, ssize_t(3)});
        py::array_t<uint32_t> triangles({t, ssize_t(3)});
        const glm::mat3 to_world_normal(normal_matrix(o.model));
        float* p = positions.mutable_data();
        float* n = normals.mutable_data();
        for (const MeshVertex& vertex : mesh.vertices) {
            const glm::vec3 world = glm::vec3(o.model * glm::vec4(vertex.position, 1.0f));
            const glm::vec3 nw = to_world_normal * vertex.normal;
            const float len = glm::length(nw);
            for (int k = 0; k < 3; ++k) *p++ = world[k], *n++ = len > 0.0f ? nw[k] / len : 0.0f;
        }
        std::memcpy(triangles.mutable_data(), mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t));
        py::dict d;
        d["positions"] = positions, d["normals"] = normals, d["triangles"] = triangles;
        return d;
    }
    std::vector<std::string> warnings() const { return model_.warnings; }
    size_t objects() const { return model_.objects.size(); }
    std::string path() const { return path_.string(); }

private:
    fs::path path_;
    ColorSpace color_ = ColorSpace::Srgb;
    Model model_;
};

}  // namespace
}  // namespace softraster::python

PYBIND11_MODULE(_softraster, m) {
    using namespace softraster;
    using namespace softraster::python;
    m.doc() = "softraster's compiled part: see help(softraster)";
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const InputError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        }
    });
    m.def(
        "render",
        [](const py::object& scene, int threads, bool depth, const std::optional<std::string>& normals, bool ids, bool linear) -> py::object {
            const Outputs want = outputs_of(depth, normals, ids, linear);
            const Scene s = scene_of(scene);
            const Rendered r = draw(s, threads, want);
            if (!want.any()) return color_array(r.color);
            return outputs(s, r, want, s.color_space);
        },
        py::arg("scene"), py::kw_only(), py::arg("threads") = 0, py::arg("depth") = false, py::arg("normals") = py::none(),
        py::arg("ids") = false, py::arg("linear") = false);
    m.def(
        "render_model",
        [](const py::object& path, const py::object& size, const std::string& view, int samples, const std::optional<std::string>& shading,
           const std::optional<std::string>& background, const std::string& color_space, const std::string& tone_mapping, float exposure,
           bool shadows, bool ssao, int threads) -> py::object {
            const PyModel model(path, color_space);
            const py::dict out =
                model.render(size, view, samples, shading, background, tone_mapping, exposure, shadows, ssao, false, std::nullopt, false, false,
                             threads, std::nullopt);
            return out["color"];  // (a py::object: an accessor into the dict would outlive it)
        },
        py::arg("path"), py::kw_only(), py::arg("size") = 512, py::arg("view") = "three-quarter", py::arg("samples") = 4,
        py::arg("shading") = py::none(), py::arg("background") = py::none(), py::arg("color_space") = "srgb",
        py::arg("tone_mapping") = "none", py::arg("exposure") = 1.0f, py::arg("shadows") = false, py::arg("ssao") = false,
        py::arg("threads") = 0);
    py::class_<PyModel>(m, "Model",
                        "A model file read once (Model(path, color_space='srgb')), to be drawn from many cameras with render().\n"
                        "Raises FileNotFoundError or ValueError (a file assimp cannot read, or with nothing to draw).")
        .def(py::init<const py::object&, const std::string&>(), py::arg("path"), py::kw_only(), py::arg("color_space") = "srgb")
        .def("render", &PyModel::render, py::kw_only(), py::arg("size") = 512, py::arg("view") = "three-quarter", py::arg("samples") = 4,
             py::arg("shading") = py::none(), py::arg("background") = py::none(), py::arg("tone_mapping") = "none",
             py::arg("exposure") = 1.0f, py::arg("shadows") = false, py::arg("ssao") = false, py::arg("depth") = false,
             py::arg("normals") = py::none(), py::arg("ids") = false, py::arg("linear") = false, py::arg("threads") = 0,
             py::arg("direction") = py::none(),
             "Draws the model, framed from `view` (or from `direction`, a vector from the model's center toward the camera), with the options of softraster.render_model.\n"
             "Returns a dict: 'color' (H x W x 4 uint8), 'camera' (K, world_to_camera in OpenCV's convention,\n"
             "world_to_camera_gl in OpenGL's), and with depth=True 'depth' (H x W float32 view-axis distance,\n"
             "inf where empty) and 'window_z'; normals='world' or 'camera': 'normals' (H x W x 3 float32, unit, 0 where\n"
             "empty); ids=True: 'object_id' and 'triangle_id' (H x W int32, -1 where empty); linear=True: 'linear'\n"
             "(H x W x 4 float32 linear light); 'draw_ms', the milliseconds spent drawing (without the\n"
             "conversion to arrays). See help(softraster) for the conventions.")
        .def("mesh", &PyModel::mesh, py::arg("object"),
             "Object `object`'s mesh in world space, as drawn: a dict of 'positions' (V x 3 float32, its node's transform\n"
             "applied), 'normals' (V x 3 float32, unit) and 'triangles' (T x 3 uint32, indices into them). Its triangle\n"
             "numbers are render(ids=True)'s 'triangle_id'.")
        .def_property_readonly("warnings", &PyModel::warnings, "What could not be used (a texture out of reach: drawn untextured)")
        .def_property_readonly("objects", &PyModel::objects, "How many objects (a mesh placed by a node) the model has")
        .def_property_readonly("path", &PyModel::path);
    m.def(
        "view_directions",
        [](int count, const std::string& layout, unsigned seed) {
            if (count < 1) throw InputError("count " + std::to_string(count) + ": expected at least 1");
            std::vector<std::array<float, 3>> out;
            for (const glm::vec3& d : view_directions(layout, count, seed)) out.push_back({d.x, d.y, d.z});
            return out;
        },
        py::arg("count"), py::kw_only(), py::arg("layout") = "sphere", py::arg("seed") = 0,
        "The camera directions of `softraster views` (unit vectors from the model's center, +y up): 'sphere' (evenly spread),\n"
        "'ring' (20 degrees above the horizon) or 'random' (uniform, the same for a seed). Use with Model.render(direction=...).");
    m.def(
        "write_png",
        [](const py::object& path, const py::array_t<uint8_t, py::array::c_style | py::array::forcecast>& rgba) {
            if (rgba.ndim() != 3 || rgba.shape(2) != 4 || rgba.shape(0) < 1 || rgba.shape(1) < 1)
                throw InputError("write_png: expected an H x W x 4 uint8 array");
            Image image(int(rgba.shape(1)), int(rgba.shape(0)));
            std::memcpy(image.pixels.data(), rgba.data(), image.pixels.size() * sizeof(Rgba8));
            const std::string file = py::module_::import("os").attr("fspath")(path).cast<std::string>();
            py::gil_scoped_release unlocked;
            try {
                write_png(image, file);
            } catch (const std::runtime_error& e) {
                py::gil_scoped_acquire locked;
                PyErr_SetString(PyExc_OSError, e.what());
                throw py::error_already_set();
            }
        },
        py::arg("path"), py::arg("rgba"),
        "Writes an H x W x 4 uint8 picture (render's color) as a PNG file, whole or not at all (a temporary name, then renamed).");
    m.attr("__version__") = SOFTRASTER_VERSION;
}

#include "gl_scene.h"
#include "gl_state.h"
#include "gl_shaders.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

namespace glref {
namespace {

using softraster::Shading;

GLuint compile(GLenum type, const std::string& defines, const char* src) {
    const GLuint s = glCreateShader(type);
    const char* parts[] = {"#version 330 core\n", defines.c_str(), kLightPrelude, src};
    glShaderSource(s, 4, parts, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048];
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        throw std::runtime_error(std::string("GLSL compile error: ") + log);
    }
    return s;
}

// World-space face normal per triangle, on fresh corners (the spec's flat shading).
softraster::Mesh flat_mesh(const softraster::Mesh& m, const glm::mat4& model) {
    softraster::Mesh out;
    for (size_t i = 0; i + 2 < m.indices.size(); i += 3) {
        softraster::MeshVertex v[3];
        glm::vec3 p[3];
        for (int k = 0; k < 3; ++k) {
            v[k] = m.vertices[m.indices[i + size_t(k)]];
            p[k] = glm::vec3(model * glm::vec4(v[k].position, 1.0f));
        }
        const glm::vec3 n = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
        for (auto& x : v) {
            x.normal = n;
            out.indices.push_back(uint32_t(out.vertices.size()));
            out.vertices.push_back(x);
        }
    }
    return out;
}

GLuint link_program(const std::string& maps, int shading, bool textured, int lights, int positional, bool cutoff, bool affine) {
    const std::string defines = maps + "#define SHADING " + std::to_string(shading) + "\n#define TEXTURED " +
                                std::to_string(int(textured)) + "\n#define LIGHTS " + std::to_string(lights) +
                                "\n#define POSITIONAL " + std::to_string(positional) +
                                "\n#define CUTOFF " + std::to_string(int(cutoff)) + "\n#define INTERP " +
                                (affine ? "noperspective" : "") + "\n";
    const GLuint program = glCreateProgram();
    glAttachShader(program, compile(GL_VERTEX_SHADER, defines, kVertexShader));
    glAttachShader(program, compile(GL_FRAGMENT_SHADER, defines, kFragmentShader));
    glLinkProgram(program);
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) throw std::runtime_error("GLSL link error");
    return program;
}

void set_enabled(GLenum cap, bool on) {
    if (on) glEnable(cap);
    else glDisable(cap);
}

GLenum gl_compare(softraster::CompareFunc f) {
    constexpr GLenum funcs[] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
    return funcs[int(f)];
}
GLenum gl_stencil_op(softraster::StencilOp op) {
    constexpr GLenum ops[] = {GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_INCR_WRAP, GL_DECR, GL_DECR_WRAP, GL_INVERT};
    return ops[int(op)];
}
GLenum gl_equation(softraster::BlendEquation e) {
    constexpr GLenum eqs[] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};
    return eqs[int(e)];
}
GLenum gl_factor(softraster::BlendFactor f) {
    constexpr GLenum factors[] = {GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_DST_COLOR, GL_ONE_MINUS_DST_COLOR,
                                  GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA, GL_CONSTANT_COLOR,
                                  GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA, GL_SRC_ALPHA_SATURATE};
    return factors[int(f)];
}

}  // namespace

struct GlScene::Draw {
    GLenum mode = GL_TRIANGLES;
    bool wire = false;          // an object's wireframe
    float extra_offset = 0.0f;  // added to the polygon offset (under a wireframe)
    glm::vec4 color{1.0f};
    GLuint program = 0;
    GLuint vao = 0, vbo = 0, ibo = 0, texture = 0;
    GLuint maps[4] = {0, 0, 0, 0};  // pbr: metallic-roughness, occlusion, emissive, normal (units 1 to 4)
    GLsizei index_count = 0;
    const softraster::SceneObject* object = nullptr;
    glm::mat4 mvp{1.0f}, model{1.0f};
    glm::mat3 normal_matrix{1.0f};
    float view_depth = 0;
    bool blended = false;

    ~Draw() {
        glDeleteVertexArrays(1, &vao);
        glDeleteBuffers(1, &vbo);
        glDeleteBuffers(1, &ibo);
    }
};

namespace {
// Uploads `mesh` and the primitives of `indices` (`per` indices each) whose vertices are all
// finite (GL leaves the others undefined). Without vertex colors: a constant white.
// Tangents: the mesh's tangent vertices, with the tangent as attribute 4.
void upload(GlScene::Draw& d, const softraster::Mesh& mesh, const std::vector<uint32_t>& indices, size_t per, bool vertex_colors,
            bool tangents = false) {
    glGenVertexArrays(1, &d.vao);
    glBindVertexArray(d.vao);
    glGenBuffers(1, &d.vbo);
    glBindBuffer(GL_ARRAY_BUFFER, d.vbo);
    const GLsizei stride = tangents ? sizeof(softraster::TangentVertex) : sizeof(softraster::MeshVertex);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.vertices.size() * size_t(stride)),
                 tangents ? static_cast<const void*>(mesh.tangent_vertices.data()) : mesh.vertices.data(), GL_STATIC_DRAW);
    if (tangents) {
        glVertexAttribPointer(4, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(softraster::TangentVertex, tangent)));
        glEnableVertexAttribArray(4);
    }
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(softraster::MeshVertex, position)));
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(softraster::MeshVertex, normal)));
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(softraster::MeshVertex, uv)));
    glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(softraster::MeshVertex, color)));
    for (GLuint a = 0; a < 3; ++a) glEnableVertexAttribArray(a);
    if (vertex_colors) glEnableVertexAttribArray(3);
    else glVertexAttrib4f(3, 1.0f, 1.0f, 1.0f, 1.0f);
    std::vector<uint32_t> idx;
    for (size_t i = 0; i + per <= indices.size(); i += per) {
        bool finite = true;
        for (size_t k = 0; k < per; ++k) {
            const glm::vec3 p = mesh.vertices[indices[i + k]].position;
            finite = finite && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
        }
        if (finite) idx.insert(idx.end(), indices.begin() + long(i), indices.begin() + long(i + per));
    }
    glGenBuffers(1, &d.ibo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, d.ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(idx.size() * 4), idx.data(), GL_STATIC_DRAW);
    d.index_count = GLsizei(idx.size());
}
}  // namespace

GlScene::GlScene(const softraster::Scene& scene)
    : scene_(scene),
      shadows_(std::make_unique<GlShadows>(scene)),
      environment_(std::make_unique<GlEnvironment>(scene.environment.get(), softraster::view_matrix(scene.camera),
                                                   softraster::projection_matrix(scene.camera, scene.width, scene.height),
                                                   scene.tone_mapping)),
      occlusion_(std::make_unique<GlAmbientOcclusion>(scene, scene.width * scene.supersample, scene.height * scene.supersample)) {

    const glm::mat4 view = softraster::view_matrix(scene.camera);
    const glm::mat4 proj = softraster::projection_matrix(scene.camera, scene.width, scene.height);
    std::map<const softraster::Texture*, GLuint> textures;
    const std::string tone_defines = "#define TONE_MAPPING " + std::to_string(int(scene.tone_mapping.active())) +
                                     "\n#define TONE_CURVE " + std::to_string(int(scene.tone_mapping.curve)) + "\n" +
                                     shadows_->defines() + environment_->defines();
    auto program = [&](int shading, bool textured, int lights, bool cutoff, bool affine, const std::string& maps = "") {
        const std::string key = maps + std::to_string(shading) + " " + std::to_string(int(textured)) + std::to_string(int(cutoff)) +
                                std::to_string(int(affine));
        GLuint& p = programs_[key];
        if (!p) p = link_program(maps + tone_defines, shading, textured, lights, int(scene.lights.punctual.size()), cutoff, affine);
        return p;
    };
    // Wide: as 16-bit texels holding the same values (v · 257 / 65535 = v / 255). llvmpipe
    // filters 8-bit textures in 8-bit arithmetic, so a filtered lookup comes back rounded to
    // 1/255; the spec's filter (and softraster's) is exact. Colors do not show the
    // difference, normal maps do (lighting magnifies a normal's error), so they go wide.
    // An sRGB texture goes up as GL_SRGB8_ALPHA8 with its stored (encoded) bytes: GL decodes
    // each texel before filtering and glGenerateMipmap averages in linear light.
    auto upload_texture = [&](const softraster::Texture* t, bool wide = false) {
        GLuint& tex = textures[t];
        if (!tex && t->srgb()) {
            std::vector<softraster::Rgba8> bytes(size_t(t->width()) * size_t(t->height()));
            for (int j = 0; j < t->height(); ++j)
                for (int i = 0; i < t->width(); ++i) bytes[size_t(j) * size_t(t->width()) + size_t(i)] = t->stored(0, i, j);
            glGenTextures(1, &tex);
            glBindTexture(GL_TEXTURE_2D, tex);
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, t->width(), t->height(), 0, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
            glGenerateMipmap(GL_TEXTURE_2D);
        }
        if (!tex) {
            // Texel row 0 is the bottom of the picture: what GL calls t = 0.
            std::vector<uint16_t> texels(size_t(t->width()) * size_t(t->height()) * 4);
            for (int j = 0; j < t->height(); ++j)
                for (int i = 0; i < t->width(); ++i) {
                    const glm::vec4 c = t->texel(i, j);
                    for (int k = 0; k < 4; ++k)
                        texels[(size_t(j) * size_t(t->width()) + size_t(i)) * 4 + size_t(k)] = uint16_t(std::lround(c[k] * 255.0f) * (wide ? 257 : 1));
                }
            std::vector<uint8_t> bytes(texels.begin(), texels.end());
            glGenTextures(1, &tex);
            glBindTexture(GL_TEXTURE_2D, tex);
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            if (wide) glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16, t->width(), t->height(), 0, GL_RGBA, GL_UNSIGNED_SHORT, texels.data());
            else glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, t->width(), t->height(), 0, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
            glGenerateMipmap(GL_TEXTURE_2D);  // GL's own chain, not softraster's
        }
        return tex;
    };
    for (const softraster::SceneObject& o : scene.objects) {
        auto d = std::make_unique<Draw>();
        d->object = &o;
        // Lines and points are drawn unlit (the spec), as the wireframe.
        const int shading = o.primitive == softraster::Topology::Triangles ? int(o.material.shading) : int(Shading::Unlit);
        d->mode = o.primitive == softraster::Topology::Triangles ? GL_TRIANGLES : o.primitive == softraster::Topology::Lines ? GL_LINES : GL_POINTS;
        d->color = o.material.color;
        const bool cutoff = o.material.alpha_cutoff.has_value();
        const softraster::Material& mat = o.material;
        const bool pbr = shading == int(Shading::Pbr);
        const softraster::Texture* maps[4] = {pbr ? mat.metallic_roughness_texture.get() : nullptr, pbr ? mat.occlusion_texture.get() : nullptr,
                                              pbr ? mat.emissive_texture.get() : nullptr, pbr ? mat.normal_texture.get() : nullptr};
        const std::string map_defines = std::string("#define MR_MAP ") + (maps[0] ? "1" : "0") + "\n#define OCCLUSION_MAP " +
                                        (maps[1] ? "1" : "0") + "\n#define EMISSIVE_MAP " + (maps[2] ? "1" : "0") +
                                        "\n#define NORMAL_MAP " + (maps[3] ? "1" : "0") + "\n";
        for (int k = 0; k < 4; ++k)
            if (maps[k]) d->maps[k] = upload_texture(maps[k], /*wide=*/k != 2);  // the data maps
        d->program = program(shading, mat.texture != nullptr, int(scene.lights.directional.size()), cutoff, mat.affine, map_defines);
        d->model = o.model;
        d->mvp = glm::mat4(glm::dmat4(proj) * glm::dmat4(view) * glm::dmat4(o.model));
        d->normal_matrix = glm::mat3(glm::transpose(glm::inverse(glm::dmat3(glm::dmat4(o.model)))));
        softraster::Mesh flat;
        const softraster::Mesh* mesh = o.mesh.get();
        if (shading == int(Shading::Flat)) {
            flat = flat_mesh(*mesh, o.model);
            mesh = &flat;
            d->normal_matrix = glm::mat3(1.0f);
        }
        const std::vector<uint32_t> indices = softraster::primitive_indices(*mesh, o.primitive);
        // Blended objects: sort key is the view depth of the object-space bounding box center.
        d->blended = o.material.blend != softraster::BlendMode::Opaque;
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        for (uint32_t i : indices) {
            const glm::vec3 p = mesh->vertices[i].position;
            if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) lo = glm::min(lo, p), hi = glm::max(hi, p);
        }
        d->view_depth = lo.x <= hi.x ? (view * o.model * glm::vec4(0.5f * (lo + hi), 1.0f)).z : 0.0f;
        upload(*d, *mesh, indices, o.primitive == softraster::Topology::Triangles ? 3 : o.primitive == softraster::Topology::Lines ? 2 : 1,
               /*vertex_colors=*/true, /*tangents=*/maps[3] != nullptr);

        if (const softraster::Texture* t = o.material.texture.get()) d->texture = upload_texture(t);
        // A wireframe: the triangles pushed back by glPolygonOffset(+1, +1), then their edges
        // as lines in one color, without vertex colors, opaque.
        std::unique_ptr<Draw> wire;
        if (o.wireframe) {
            d->extra_offset = 1.0f;
            wire = std::make_unique<Draw>();
            wire->object = &o;
            wire->wire = true;
            wire->mode = GL_LINES;
            wire->color = glm::vec4(o.wireframe->color, 1.0f);
            wire->program = program(int(Shading::Unlit), false, int(scene.lights.directional.size()), false, false);
            wire->mvp = d->mvp;
            wire->blended = d->blended;
            wire->view_depth = d->view_depth;
            upload(*wire, *mesh, softraster::triangle_edges(*mesh), 2, /*vertex_colors=*/false);
        }
        draws_.push_back(std::move(d));
        if (wire) draws_.push_back(std::move(wire));
    }
    // Opaque first in file order, then blended farthest first (stable: ties keep file order).
    // (Version 2's draw_order "file": all in file order.)
    if (scene.sorted) std::stable_sort(draws_.begin(), draws_.end(), [](const auto& a, const auto& b) {
        if (a->blended != b->blended) return !a->blended;
        return a->blended && a->view_depth < b->view_depth;
    });
    for (const auto& d : draws_)
        if (d->mode == GL_TRIANGLES && !d->blended && !d->wire) {
            casters_.push_back({d->vao, d->index_count, d->model});
            occluders_.push_back({d->vao, d->index_count, d->model, d->object->cull, d->object->front_face});
        }
    if (glGetError() != GL_NO_ERROR) throw std::runtime_error("OpenGL error while uploading the scene");
}

GlScene::~GlScene() {
    draws_.clear();
    for (const auto& [key, program] : programs_) glDeleteProgram(program);
}

void GlScene::apply_ambient_occlusion(softraster::Image& picture) const {
    if (occlusion_->active()) softraster::apply_ambient_occlusion(picture, occlusion_->factors(), scene_.color_space);
}

void GlScene::draw_frame() const {
    shadows_->draw(casters_);
    occlusion_->draw_depth(occluders_);
    const glm::vec4 bg = scene_.background;
    glClearColor(bg.r, bg.g, bg.b, bg.a);
    glClearDepth(1.0);
    glClearStencil(scene_.clear_stencil);
    glDepthMask(GL_TRUE);
    glStencilMask(0xff);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_SCISSOR_TEST);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    environment_->draw_sky();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_MULTISAMPLE);
    const softraster::Lights& lights = scene_.lights;
    for (const auto& d : draws_) {
        glUseProgram(d->program);
        shadows_->bind(d->program);
        environment_->bind(d->program);
        auto loc = [&](const char* n) { return glGetUniformLocation(d->program, n); };
        glUniform3fv(loc("u_ambient"), 1, glm::value_ptr(lights.ambient));
        for (size_t i = 0; i < lights.directional.size(); ++i) {
            const glm::vec3 l = -glm::normalize(lights.directional[i].direction);
            glUniform3fv(loc(("u_to_light[" + std::to_string(i) + "]").c_str()), 1, glm::value_ptr(l));
            glUniform3fv(loc(("u_light_color[" + std::to_string(i) + "]").c_str()), 1, glm::value_ptr(lights.directional[i].color));
        }
        for (size_t i = 0; i < lights.punctual.size(); ++i) {
            const softraster::PunctualLight& l = lights.punctual[i];
            auto at = [&](const char* name) { return loc((std::string(name) + "[" + std::to_string(i) + "]").c_str()); };
            glUniform3fv(at("u_pl_position"), 1, glm::value_ptr(l.position));
            glUniform3fv(at("u_pl_color"), 1, glm::value_ptr(l.color * l.intensity));
            glUniform1f(at("u_pl_inv_range2"), l.range > 0.0f ? 1.0f / (l.range * l.range) : 0.0f);
            glUniform3fv(at("u_pl_spot_dir"), 1, glm::value_ptr(glm::normalize(l.direction)));
            const float cos_outer = std::cos(glm::radians(l.outer_angle)), cos_inner = std::cos(glm::radians(l.inner_angle));
            const float scale = 1.0f / std::max(1e-3f, cos_inner - cos_outer);
            glUniform2f(at("u_pl_cone"), l.spot ? scale : 0.0f, l.spot ? -cos_outer * scale : 1.0f);
        }
        glUniform3fv(loc("u_eye"), 1, glm::value_ptr(scene_.camera.eye));
        glUniform1i(loc("u_texture"), 0);
        const softraster::SceneObject& o = *d->object;
        const softraster::Material& m = o.material;
        glUniformMatrix4fv(loc("u_mvp"), 1, GL_FALSE, glm::value_ptr(d->mvp));
        glUniformMatrix4fv(loc("u_model"), 1, GL_FALSE, glm::value_ptr(d->model));
        glUniformMatrix3fv(loc("u_normal_matrix"), 1, GL_FALSE, glm::value_ptr(d->normal_matrix));
        glUniform4fv(loc("u_color"), 1, glm::value_ptr(d->color));
        glUniform3fv(loc("u_specular"), 1, glm::value_ptr(m.specular));
        glUniform1f(loc("u_shininess"), m.shininess);
        glUniform1f(loc("u_metallic"), m.metallic);
        glUniform1f(loc("u_roughness"), m.roughness);
        glUniform1f(loc("u_occlusion_strength"), m.occlusion_strength);
        glUniform3fv(loc("u_emissive"), 1, glm::value_ptr(m.emissive));
        glUniform1i(loc("u_mr_texture"), 1);
        glUniform1i(loc("u_occlusion_texture"), 2);
        glUniform1i(loc("u_emissive_texture"), 3);
        glUniform1i(loc("u_normal_texture"), 4);
        glUniform1f(loc("u_normal_scale"), m.normal_scale);
        for (int unit = 0; unit < 5; ++unit) {
            const GLuint tex = unit == 0 ? d->texture : d->maps[unit - 1];
            if (!tex || d->wire) continue;
            glActiveTexture(GLenum(GL_TEXTURE0 + unit));
            glBindTexture(GL_TEXTURE_2D, tex);
            const softraster::Sampler& s = m.sampler;
            using softraster::Filter, softraster::MipFilter;
            auto wrap = [](softraster::Wrap w) -> GLint {
                switch (w) {
                    case softraster::Wrap::Repeat: return GL_REPEAT;
                    case softraster::Wrap::Clamp: return GL_CLAMP_TO_EDGE;
                    case softraster::Wrap::Mirror: return GL_MIRRORED_REPEAT;
                    case softraster::Wrap::Border: return GL_CLAMP_TO_BORDER;
                }
                return GL_REPEAT;
            };
            const bool lin = s.min == Filter::Bilinear;
            const GLint min = s.mip == MipFilter::None      ? (lin ? GL_LINEAR : GL_NEAREST)
                              : s.mip == MipFilter::Nearest ? (lin ? GL_LINEAR_MIPMAP_NEAREST : GL_NEAREST_MIPMAP_NEAREST)
                                                            : (lin ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, s.mag == Filter::Nearest ? GL_NEAREST : GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap(s.wrap_s));
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap(s.wrap_t));
            glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, glm::value_ptr(s.border));
            // llvmpipe's anisotropic filter is an elliptical (EWA) one, ours takes probes along
            // the long axis as the extension describes: the same state, not the same pixels
            // (docs/scene-format.md "Texture sampling").
            if (s.max_anisotropy > 1) glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY, float(s.max_anisotropy));
        }
        glActiveTexture(GL_TEXTURE0);
        set_faces(o.cull, o.front_face);
        glUniform1f(loc("u_alpha_cutoff"), m.alpha_cutoff.value_or(0.0f));
        glUniform1f(loc("u_exposure"), scene_.tone_mapping.exposure);
        const softraster::ObjectState& st = o.state;
        const bool blended = m.blend != softraster::BlendMode::Opaque && !d->wire;
        set_enabled(GL_DEPTH_TEST, st.depth_test);
        glDepthFunc(gl_compare(st.depth_func));
        glDepthMask(st.depth_write.value_or(!blended) ? GL_TRUE : GL_FALSE);  // blended objects do not write by default
        const float factor = st.offset_factor + d->extra_offset, units = st.offset_units + d->extra_offset;
        set_enabled(GL_POLYGON_OFFSET_FILL, factor != 0.0f || units != 0.0f);
        glPolygonOffset(factor, units);
        glLineWidth(d->wire ? o.wireframe->width : o.line_width);
        glPointSize(o.point_size);
        set_enabled(GL_STENCIL_TEST, st.stencil_test);
        for (const auto& [face, f] : {std::pair{GLenum(GL_FRONT), st.stencil_front}, std::pair{GLenum(GL_BACK), st.stencil_back}}) {
            glStencilFuncSeparate(face, gl_compare(f.func), f.ref, f.read_mask);
            glStencilMaskSeparate(face, f.write_mask);
            glStencilOpSeparate(face, gl_stencil_op(f.fail), gl_stencil_op(f.depth_fail), gl_stencil_op(f.pass));
        }
        set_enabled(GL_SCISSOR_TEST, st.scissor.has_value());
        if (st.scissor) {  // window row 0 is the top row of the picture (see the vertex shader)
            const int k = scene_.supersample;
            glScissor(st.scissor->x * k, st.scissor->y * k, st.scissor->width * k, st.scissor->height * k);
        }
        glColorMask(m.color_mask & 1, (m.color_mask >> 1) & 1, (m.color_mask >> 2) & 1, (m.color_mask >> 3) & 1);
        set_enabled(GL_SAMPLE_ALPHA_TO_COVERAGE, m.alpha_to_coverage && !d->wire);
        set_enabled(GL_BLEND, blended);
        const softraster::BlendEquationState b =
            m.blend == softraster::BlendMode::Custom ? m.blend_equation : softraster::blend_preset(m.blend);
        glBlendEquationSeparate(gl_equation(b.rgb), gl_equation(b.alpha));
        glBlendFuncSeparate(gl_factor(b.src_rgb), gl_factor(b.dst_rgb), gl_factor(b.src_alpha), gl_factor(b.dst_alpha));
        glBlendColor(b.constant.r, b.constant.g, b.constant.b, b.constant.a);
        glBindVertexArray(d->vao);
        glDrawElements(d->mode, d->index_count, GL_UNSIGNED_INT, nullptr);
    }
    glDepthMask(GL_TRUE);
    glStencilMask(0xff);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
}

}  // namespace glref

// Wavefront OBJ reader (the subset the scene format defines; see spec "Meshes").
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <tuple>

#include "io/read_file.h"
#include "io/text_parse.h"
#include "softraster/error.h"
#include "softraster/scene/mesh.h"

namespace softraster {
namespace {

struct Corner {
    int64_t v = 0, t = -1, n = -1;  // 0-based; -1 = absent
    auto operator<=>(const Corner&) const = default;
};

struct ObjReader {
    std::string name;
    size_t line_no = 0;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec4> colors;  // per position
    std::vector<glm::vec2> uvs;
    std::vector<glm::vec3> normals;
    std::vector<std::array<Corner, 3>> triangles;
    std::vector<Corner> lines;   // two per segment
    std::vector<Corner> points;

    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(name + ":" + std::to_string(line_no) + ": " + what);
    }

    double number(std::string_view tok, bool allow_non_finite) const {
        double d;
        if (!parse_double(tok, d)) fail("'" + std::string(tok) + "' is not a number");
        if (!allow_non_finite && !std::isfinite(d)) fail("non-finite number '" + std::string(tok) + "'");
        return d;
    }

    // A 1-based (or negative, relative) index into a list that has `count` entries so far.
    int64_t index(std::string_view tok, size_t count, const char* what) const {
        int64_t i;
        if (!parse_int64(tok, i)) fail(std::string("bad ") + what + " index '" + std::string(tok) + "'");
        if (i == 0) fail(std::string(what) + " index 0 (OBJ indices start at 1)");
        if (i < 0) {
            i += int64_t(count);
            if (i < 0) fail(std::string(what) + " index " + std::string(tok) + " out of range (" + std::to_string(count) + " defined)");
            return i;
        }
        return i - 1;  // checked against the final count at the end (forward references)
    }

    Corner corner(std::string_view tok) const {
        Corner c;
        const size_t s1 = tok.find('/');
        c.v = index(tok.substr(0, s1), positions.size(), "vertex");
        if (s1 == std::string_view::npos) return c;
        const std::string_view rest = tok.substr(s1 + 1);
        const size_t s2 = rest.find('/');
        const std::string_view t = rest.substr(0, s2);
        if (!t.empty()) c.t = index(t, uvs.size(), "texture coordinate");
        if (s2 != std::string_view::npos) {
            const std::string_view n = rest.substr(s2 + 1);
            if (n.empty() && t.empty()) fail("bad face corner '" + std::string(tok) + "'");
            if (!n.empty()) c.n = index(n, normals.size(), "normal");
        }
        return c;
    }

    // A corner of a line or point: v or v/vt (no normals).
    Corner element_corner(std::string_view tok) const {
        const Corner c = corner(tok);
        if (c.n >= 0) fail("a line or point corner has no normal ('" + std::string(tok) + "')");
        return c;
    }

    void statement(const std::vector<std::string_view>& tok) {
        const std::string_view kw = tok[0];
        const size_t args = tok.size() - 1;
        if (kw == "v") {
            if (args < 3) fail("vertex needs 3 coordinates, got " + std::to_string(args));
            positions.emplace_back(float(number(tok[1], true)), float(number(tok[2], true)), float(number(tok[3], true)));
            glm::vec4 color(1.0f);
            if (args == 6) {
                color = glm::vec4(float(number(tok[4], false)), float(number(tok[5], false)), float(number(tok[6], false)), 1.0f);
            } else {
                for (size_t i = 4; i < tok.size(); ++i) number(tok[i], true);  // optional w etc.: ignored, but numbers
            }
            colors.push_back(color);
        } else if (kw == "vt") {
            if (args < 1) fail("texture coordinate needs at least 1 number");
            const float u = float(number(tok[1], false));
            const float v = args >= 2 ? float(number(tok[2], false)) : 0.0f;
            for (size_t i = 3; i < tok.size(); ++i) number(tok[i], false);
            uvs.emplace_back(u, v);
        } else if (kw == "vn") {
            if (args < 3) fail("normal needs 3 numbers, got " + std::to_string(args));
            normals.emplace_back(float(number(tok[1], false)), float(number(tok[2], false)), float(number(tok[3], false)));
        } else if (kw == "f") {
            if (args < 3) fail("face needs at least 3 corners, got " + std::to_string(args));
            const Corner first = corner(tok[1]);
            Corner prev = corner(tok[2]);
            for (size_t i = 3; i < tok.size(); ++i) {  // fan (0, i, i+1)
                const Corner cur = corner(tok[i]);
                triangles.push_back({first, prev, cur});
                prev = cur;
            }
        } else if (kw == "l") {  // a polyline: v1 v2 ... as segments (v1, v2), (v2, v3), ...
            if (args < 2) fail("line needs at least 2 vertices, got " + std::to_string(args));
            for (size_t i = 1; i + 1 < tok.size(); ++i) {
                lines.push_back(element_corner(tok[i]));
                lines.push_back(element_corner(tok[i + 1]));
            }
        } else if (kw == "p") {
            if (args < 1) fail("point needs at least 1 vertex");
            for (size_t i = 1; i < tok.size(); ++i) points.push_back(element_corner(tok[i]));
        } else if (kw == "g" || kw == "o" || kw == "s" || kw == "mtllib" || kw == "usemtl" ||
                   kw == "vp" || kw == "mg" || kw == "lod" || kw == "maplib" || kw == "usemap" || kw == "shadow_obj" ||
                   kw == "trace_obj" || kw == "bevel" || kw == "c_interp" || kw == "d_interp" || kw == "cstype" ||
                   kw == "deg" || kw == "bmat" || kw == "step" || kw == "curv" || kw == "curv2" || kw == "surf" ||
                   kw == "parm" || kw == "trim" || kw == "hole" || kw == "scrv" || kw == "sp" || kw == "end" ||
                   kw == "con" || kw == "ctech" || kw == "stech") {
            // Read but not used in version 1: the scene's material applies to the whole object.
        } else {
            fail("unknown statement '" + std::string(kw.substr(0, 40)) + "' (is this an OBJ file?)");
        }
    }

    Mesh build() {
        // Check indices against the final counts (OBJ allows forward references).
        auto check = [&](const Corner& c) {
            if (c.v >= int64_t(positions.size()))
                throw InputError(name + ": vertex index " + std::to_string(c.v + 1) + " out of range (" + std::to_string(positions.size()) + " vertices)");
            if (c.t >= int64_t(uvs.size()))
                throw InputError(name + ": texture coordinate index " + std::to_string(c.t + 1) + " out of range (" + std::to_string(uvs.size()) + " defined)");
            if (c.n >= int64_t(normals.size()))
                throw InputError(name + ": normal index " + std::to_string(c.n + 1) + " out of range (" + std::to_string(normals.size()) + " defined)");
        };
        for (const auto& tri : triangles)
            for (const Corner& c : tri) check(c);
        for (const Corner& c : lines) check(c);
        for (const Corner& c : points) check(c);
        Mesh mesh;
        std::map<Corner, uint32_t> cache;  // each distinct (v, vt, vn) becomes one vertex
        auto make = [&](const Corner& c) {
            MeshVertex v;
            v.position = positions[size_t(c.v)];
            if (c.t >= 0) v.uv = uvs[size_t(c.t)];
            if (c.n >= 0) v.normal = normals[size_t(c.n)];
            v.color = colors[size_t(c.v)];
            return v;
        };
        auto vertex = [&](const Corner& c) {
            auto [it, inserted] = cache.try_emplace(c, uint32_t(mesh.vertices.size()));
            if (inserted) mesh.vertices.push_back(make(c));
            return it->second;
        };
        for (const auto& tri : triangles) {
            if (tri[0].n < 0 || tri[1].n < 0 || tri[2].n < 0) {
                mesh.add_face_normal_triangle(make(tri[0]), make(tri[1]), make(tri[2]));
                continue;
            }
            for (const Corner& c : tri) mesh.indices.push_back(vertex(c));
        }
        for (const Corner& c : lines) mesh.lines.push_back(vertex(c));
        for (const Corner& c : points) mesh.points.push_back(vertex(c));
        return mesh;
    }
};

// The next statement of an OBJ text from `pos` on, as common tools write them: LF or CRLF
// line ends, and a backslash at a line's end continuing the statement on the next line.
// Advances pos and `lines` (the physical lines read); a continued statement is joined in
// `joined`, any other is a view of the text.
std::string_view next_statement(const std::string& text, size_t& pos, size_t& lines, std::string& joined) {
    joined.clear();
    for (;;) {
        size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        ++lines;
        std::string_view part(text.data() + pos, end - pos);
        pos = end + 1;
        while (!part.empty() && (part.back() == '\r' || part.back() == ' ' || part.back() == '\t')) part.remove_suffix(1);
        const bool continued = part.ends_with('\\') && pos < text.size();
        if (!continued && joined.empty()) return part;  // (the usual case: no copy)
        if (continued) part.remove_suffix(1);
        joined.append(part).push_back(' ');
        if (!continued) return joined;
    }
}

}  // namespace

Mesh load_obj(const std::filesystem::path& path) {
    ObjReader r;
    r.name = path.string();
    const std::string text = read_whole_file(path);
    size_t pos = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;  // a UTF-8 byte-order mark
    std::string joined;
    size_t lines = 0;
    while (pos < text.size()) {
        r.line_no = lines + 1;  // errors name the statement's first line
        std::string_view line = next_statement(text, pos, lines, joined);
        if (const size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        if (line.find('\0') != std::string_view::npos) r.fail("binary data (is this an OBJ file?)");
        const auto tok = split_tokens(line);  // (tabs separate too)
        if (!tok.empty()) r.statement(tok);
    }
    return r.build();
}

}  // namespace softraster

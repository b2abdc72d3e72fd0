// Stanford PLY reader: ascii and binary (both byte orders), see spec "Meshes".
#include <bit>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>

#include "io/read_file.h"
#include "io/text_parse.h"
#include "softraster/error.h"
#include "softraster/scene/mesh.h"

namespace softraster {
namespace {

enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::optional<Type> type_from_name(std::string_view n) {
    if (n == "char" || n == "int8") return Type::Int8;
    if (n == "uchar" || n == "uint8") return Type::UInt8;
    if (n == "short" || n == "int16") return Type::Int16;
    if (n == "ushort" || n == "uint16") return Type::UInt16;
    if (n == "int" || n == "int32") return Type::Int32;
    if (n == "uint" || n == "uint32") return Type::UInt32;
    if (n == "float" || n == "float32") return Type::Float32;
    if (n == "double" || n == "float64") return Type::Float64;
    return std::nullopt;
}
size_t type_size(Type t) {
    switch (t) {
        case Type::Int8: case Type::UInt8: return 1;
        case Type::Int16: case Type::UInt16: return 2;
        case Type::Float64: return 8;
        default: return 4;
    }
}
bool is_integer(Type t) { return t != Type::Float32 && t != Type::Float64; }

struct Property {
    std::string name;
    Type type = Type::Float32;
    bool is_list = false;
    Type count_type = Type::UInt8;
};

struct Element {
    std::string name;
    uint64_t count = 0;
    std::vector<Property> props;
};

enum class Format { Ascii, BinaryLE, BinaryBE };

// ---- header

struct Header {
    Format format = Format::Ascii;
    std::vector<Element> elements;
    size_t body_start = 0;  // byte offset of the first byte after end_header's line
    size_t body_line = 1;   // its line number (ascii bodies count lines in errors)
};

Header parse_header(const std::string& name, const std::string& text) {
    auto fail_at = [&](size_t line, const std::string& what) -> InputError {
        return InputError(name + ":" + std::to_string(line) + ": " + what);
    };
    Header h;
    size_t pos = 0, line_no = 0;
    bool have_format = false, ended = false;
    while (pos < text.size() && !ended) {
        size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        const std::string_view line(text.data() + pos, end - pos);
        pos = end + 1;
        ++line_no;
        const auto tok = split_tokens(line);
        if (line_no == 1) {
            if (tok.size() != 1 || tok[0] != "ply") throw fail_at(1, "not a PLY file (first line is not 'ply')");
            continue;
        }
        if (tok.empty()) throw fail_at(line_no, "empty header line");
        const std::string_view kw = tok[0];
        if (kw == "format") {
            if (tok.size() != 3) throw fail_at(line_no, "bad format line");
            if (tok[1] == "ascii") h.format = Format::Ascii;
            else if (tok[1] == "binary_little_endian") h.format = Format::BinaryLE;
            else if (tok[1] == "binary_big_endian") h.format = Format::BinaryBE;
            else throw fail_at(line_no, "unknown format '" + std::string(tok[1]) + "'");
            have_format = true;
        } else if (kw == "comment" || kw == "obj_info") {
        } else if (kw == "element") {
            int64_t count;
            if (tok.size() != 3 || !parse_int64(tok[2], count) || count < 0)
                throw fail_at(line_no, "bad element line (expected 'element NAME COUNT')");
            h.elements.push_back({std::string(tok[1]), uint64_t(count), {}});
        } else if (kw == "property") {
            if (h.elements.empty()) throw fail_at(line_no, "property before any element");
            Property p;
            if (tok.size() == 5 && tok[1] == "list") {
                const auto ct = type_from_name(tok[2]), it = type_from_name(tok[3]);
                if (!ct || !it) throw fail_at(line_no, "unknown property type");
                if (!is_integer(*ct)) throw fail_at(line_no, "list count type must be an integer type");
                p = {std::string(tok[4]), *it, true, *ct};
            } else if (tok.size() == 3) {
                const auto t = type_from_name(tok[1]);
                if (!t) throw fail_at(line_no, "unknown property type '" + std::string(tok[1]) + "'");
                p = {std::string(tok[2]), *t, false, Type::UInt8};
            } else {
                throw fail_at(line_no, "bad property line");
            }
            h.elements.back().props.push_back(p);
        } else if (kw == "end_header") {
            ended = true;
        } else {
            throw fail_at(line_no, "unexpected header line '" + std::string(kw.substr(0, 40)) + "'");
        }
    }
    if (!ended) throw InputError(name + ": PLY header has no end_header (truncated?)");
    if (!have_format) throw InputError(name + ": PLY header has no format line");
    h.body_start = pos;
    h.body_line = line_no + 1;
    return h;
}

// ---- what the vertex and face elements hold

struct Layout {
    int x = -1, y = -1, z = -1, nx = -1, ny = -1, nz = -1, u = -1, v = -1, r = -1, g = -1, b = -1, a = -1;
    int face_list = -1;
    const Element* vertex_el = nullptr;  // the first "vertex" and "face" elements
    const Element* face_el = nullptr;
};

Layout find_layout(const std::string& name, const std::vector<Element>& elements) {
    Layout L;
    for (const Element& e : elements) {
        auto find = [&](const char* n) {
            for (size_t i = 0; i < e.props.size(); ++i)
                if (e.props[i].name == n) return int(i);
            return -1;
        };
        if (e.name == "vertex" && !L.vertex_el) {
            L.vertex_el = &e;
            L.x = find("x"), L.y = find("y"), L.z = find("z");
            if (L.x < 0 || L.y < 0 || L.z < 0) throw InputError(name + ": vertex element lacks x, y or z");
            L.nx = find("nx"), L.ny = find("ny"), L.nz = find("nz");
            if (L.nx < 0 || L.ny < 0 || L.nz < 0) L.nx = L.ny = L.nz = -1;
            for (auto [un, vn] : {std::pair{"u", "v"}, std::pair{"s", "t"}, std::pair{"texture_u", "texture_v"}})
                if (find(un) >= 0 && find(vn) >= 0) {
                    L.u = find(un), L.v = find(vn);
                    break;
                }
            L.r = find("red"), L.g = find("green"), L.b = find("blue"), L.a = find("alpha");
            if (L.r < 0 || L.g < 0 || L.b < 0) L.r = L.g = L.b = L.a = -1;
            for (int c : {L.r, L.g, L.b, L.a}) {
                if (c < 0) continue;
                const Property& p = e.props[size_t(c)];
                if (p.is_list || (p.type != Type::UInt8 && p.type != Type::Float32 && p.type != Type::Float64))
                    throw InputError(name + ": color property '" + p.name + "' must be uchar, float or double");
            }
            for (int c : {L.x, L.y, L.z})
                if (e.props[size_t(c)].is_list) throw InputError(name + ": vertex position cannot be a list");
        } else if (e.name == "face" && !L.face_el) {
            L.face_el = &e;
            L.face_list = find("vertex_indices");
            if (L.face_list < 0) L.face_list = find("vertex_index");
            if (L.face_list < 0) throw InputError(name + ": face element lacks vertex_indices");
            const Property& p = e.props[size_t(L.face_list)];
            if (!p.is_list) throw InputError(name + ": vertex_indices must be a list");
            if (!is_integer(p.type)) throw InputError(name + ": vertex_indices must have an integer type");
        }
    }
    if (!L.vertex_el) throw InputError(name + ": no vertex element");
    return L;
}

// ---- the body: values one at a time, as text or as binary numbers

class AsciiBody {
public:
    AsciiBody(const std::string& name, const std::string& text, size_t pos, size_t line)
        : name_(name), text_(text), pos_(pos), line_(line) {}

    double read(Type t) {
        for (;;) {  // skip whitespace, counting lines
            if (pos_ >= text_.size()) fail("file ends early (truncated?)");
            const char c = text_[pos_];
            if (c == '\n') ++line_;
            if (c != ' ' && c != '\t' && c != '\r' && c != '\n') break;
            ++pos_;
        }
        const size_t start = pos_;
        while (pos_ < text_.size() && !std::strchr(" \t\r\n", text_[pos_])) ++pos_;
        const std::string_view tok(text_.data() + start, pos_ - start);
        if (is_integer(t)) {
            int64_t v;
            if (!parse_int64(tok, v)) fail_token(tok, "is not an integer");
            return double(v);
        }
        double d;
        if (!parse_double(tok, d)) fail_token(tok, "is not a number");
        return d;
    }
    [[noreturn]] void fail(const std::string& what) const { throw InputError(name_ + ":" + std::to_string(line_) + ": " + what); }

private:
    // Out of line and cold: the message is built only on the error path.
    [[noreturn, gnu::noinline, gnu::cold]] void fail_token(std::string_view tok, const char* what) const {
        std::string message = "'";
        message.append(tok.substr(0, 40));
        message += "' ";
        message += what;
        fail(message);
    }

    const std::string& name_;
    const std::string& text_;
    size_t pos_, line_;
};

class BinaryBody {
public:
    BinaryBody(const std::string& name, const std::string& text, size_t pos, bool big_endian)
        : name_(name), text_(text), pos_(pos), swap_(big_endian == (std::endian::native == std::endian::little)) {}

    double read(Type t) {
        const size_t n = type_size(t);
        if (pos_ + n > text_.size()) fail("truncated binary data (file ends early)");
        unsigned char b[8];
        std::memcpy(b, text_.data() + pos_, n);
        pos_ += n;
        if (swap_)
            for (size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
        switch (t) {
            case Type::Int8: { int8_t v; std::memcpy(&v, b, 1); return v; }
            case Type::UInt8: return b[0];
            case Type::Int16: { int16_t v; std::memcpy(&v, b, 2); return v; }
            case Type::UInt16: { uint16_t v; std::memcpy(&v, b, 2); return v; }
            case Type::Int32: { int32_t v; std::memcpy(&v, b, 4); return v; }
            case Type::UInt32: { uint32_t v; std::memcpy(&v, b, 4); return v; }
            case Type::Float32: { float v; std::memcpy(&v, b, 4); return double(v); }
            case Type::Float64: { double v; std::memcpy(&v, b, 8); return v; }
        }
        return 0;
    }
    [[noreturn]] void fail(const std::string& what) const { throw InputError(name_ + ": " + what); }

private:
    const std::string& name_;
    const std::string& text_;
    size_t pos_;
    bool swap_;
};

// Reads every element of the body in order with `in`, keeping the vertices and the faces'
// triangles (fanned) of the layout's elements and skipping the rest.
template <class Body>
void read_body(Body& in, const Header& h, const Layout& L, size_t file_size, std::vector<MeshVertex>& verts,
               std::vector<uint32_t>& tris) {
    std::vector<double> val;
    for (const Element& e : h.elements) {
        const bool is_vertex = &e == L.vertex_el, is_face = &e == L.face_el;
        if (is_vertex && e.count > file_size) in.fail("vertex count " + std::to_string(e.count) + " exceeds the file size");
        for (uint64_t k = 0; k < e.count; ++k) {
            val.assign(e.props.size(), 0.0);
            for (size_t pi = 0; pi < e.props.size(); ++pi) {
                const Property& p = e.props[pi];
                if (!p.is_list) {
                    val[pi] = in.read(p.type);
                    continue;
                }
                const double n = in.read(p.count_type);
                if (n < 0 || n > double(file_size)) in.fail("bad list length " + std::to_string(int64_t(n)));
                if (is_face && int(pi) == L.face_list) {
                    if (n < 3) in.fail("face with " + std::to_string(int64_t(n)) + " corners (need at least 3)");
                    uint32_t first = 0, prev = 0;
                    for (int64_t c = 0; c < int64_t(n); ++c) {
                        const double idx = in.read(p.type);
                        if (idx < 0 || idx >= double(verts.size()))
                            in.fail("face index " + std::to_string(int64_t(idx)) + " out of range (" + std::to_string(verts.size()) + " vertices)");
                        const auto i = uint32_t(idx);
                        if (c == 0) first = i;
                        else if (c >= 2) tris.insert(tris.end(), {first, prev, i});  // fan (0, c-1, c)
                        prev = i;
                    }
                } else {
                    for (int64_t c = 0; c < int64_t(n); ++c) in.read(p.type);  // skipped
                }
            }
            if (!is_vertex) continue;
            auto get = [&](int i) { return val[size_t(i)]; };
            auto finite = [&](int i, const char* what) {
                if (!std::isfinite(get(i))) in.fail(std::string("non-finite ") + what + " in vertex " + std::to_string(k));
                return float(get(i));
            };
            MeshVertex v;
            v.position = glm::vec3(float(get(L.x)), float(get(L.y)), float(get(L.z)));
            if (L.nx >= 0) v.normal = glm::vec3(finite(L.nx, "normal"), finite(L.ny, "normal"), finite(L.nz, "normal"));
            if (L.u >= 0) v.uv = glm::vec2(finite(L.u, "texture coordinate"), finite(L.v, "texture coordinate"));
            if (L.r >= 0) {
                auto channel = [&](int i) {
                    const float c = finite(i, "color");
                    return e.props[size_t(i)].type == Type::UInt8 ? c / 255.0f : c;
                };
                v.color = glm::vec4(channel(L.r), channel(L.g), channel(L.b), L.a >= 0 ? channel(L.a) : 1.0f);
            }
            verts.push_back(v);
        }
    }
}

}  // namespace

Mesh load_ply(const std::filesystem::path& path) {
    const std::string name = path.string();
    const std::string text = read_whole_file(path);
    const Header header = parse_header(name, text);
    const Layout layout = find_layout(name, header.elements);
    std::vector<MeshVertex> verts;
    std::vector<uint32_t> tris;  // indices into verts
    if (header.format == Format::Ascii) {
        AsciiBody in(name, text, header.body_start, header.body_line);
        read_body(in, header, layout, text.size(), verts, tris);
    } else {
        BinaryBody in(name, text, header.body_start, header.format == Format::BinaryBE);
        read_body(in, header, layout, text.size(), verts, tris);
    }

    Mesh mesh;
    if (layout.nx >= 0) {
        mesh.vertices = std::move(verts);
        mesh.indices = std::move(tris);
    } else {
        for (size_t i = 0; i + 2 < tris.size(); i += 3)
            mesh.add_face_normal_triangle(verts[tris[i]], verts[tris[i + 1]], verts[tris[i + 2]]);
    }
    return mesh;
}

}  // namespace softraster

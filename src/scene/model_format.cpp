#include "scene/model_format.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string_view>

namespace softraster {
namespace {

bool starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

uint32_t little_u32(const char* p) {
    uint32_t v;
    std::memcpy(&v, p, 4);  // (x86 and every platform Debian builds this for that matters here are little-endian)
    return v;
}

// The first non-blank characters of the text, skipping a UTF-8 byte order mark.
std::string_view trimmed(std::string_view s) {
    if (starts_with(s, "\xEF\xBB\xBF")) s.remove_prefix(3);
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r' || s.front() == '\n')) s.remove_prefix(1);
    return s;
}

// Lines of an OBJ: vertices ("v ") and faces ("f ") among comments and other keywords only.
bool looks_like_obj(std::string_view s) {
    bool vertex = false, face = false;
    for (size_t at = 0; at < s.size();) {
        const size_t end = std::min(s.find('\n', at), s.size());
        const std::string_view line = trimmed(s.substr(at, end - at));
        if (starts_with(line, "v ")) vertex = true;
        else if (starts_with(line, "f ")) face = true;
        at = end + 1;
    }
    return vertex && face;
}

}  // namespace

std::string model_format_of_content(const std::filesystem::path& path, bool extension_known) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return "";
    char buffer[4096];
    in.read(buffer, sizeof buffer);
    const std::string_view head(buffer, size_t(in.gcount()));
    std::error_code ec;
    const uint64_t size = std::filesystem::file_size(path, ec);
    if (ec) return "";

    if (starts_with(head, "glTF")) return ".glb";
    if (starts_with(head, "ply\n") || starts_with(head, "ply\r")) return ".ply";
    if (starts_with(head, "Kaydara FBX Binary")) return ".fbx";
    if (starts_with(head, "xof ")) return ".x";
    // 3DS: a main chunk (id 0x4d4d) whose length is the file's.
    if (head.size() >= 6 && head[0] == 0x4d && head[1] == 0x4d && little_u32(head.data() + 2) == size) return ".3ds";
    // Binary STL: an 80-byte header, a triangle count, 50 bytes per triangle.
    if (head.size() >= 84 && size == 84 + 50 * uint64_t(little_u32(head.data() + 80))) return ".stl";
    const std::string_view text = trimmed(head);
    if (starts_with(text, "solid") && head.find("facet") != std::string_view::npos) return ".stl";
    if (starts_with(text, "OFF")) return ".off";
    if (starts_with(text, "<") && head.find("<COLLADA") != std::string_view::npos) return ".dae";
    if (starts_with(text, "{") && head.find("\"asset\"") != std::string_view::npos) return ".gltf";
    if (!extension_known && looks_like_obj(head)) return ".obj";
    return "";
}

}  // namespace softraster

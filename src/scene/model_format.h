// What format a model file's bytes are, whatever its name says. A thumbnailer is handed
// files named by a file manager, and downloads get misnamed; assimp picks its importer by
// the extension, so a file whose extension lies or is missing would not be read.
#pragma once
#include <filesystem>
#include <string>

namespace softraster {

// The extension (".glb", ".ply"...) of the format the file's first bytes show, or "" for
// none recognized. Formats with a signature of their own are recognized wherever found (GLB,
// glTF's JSON, PLY, binary FBX, COLLADA, 3DS, DirectX, OFF, binary and ASCII STL); OBJ, which
// has none, only when `extension_known` is false and its lines look like one.
std::string model_format_of_content(const std::filesystem::path& path, bool extension_known);

}  // namespace softraster

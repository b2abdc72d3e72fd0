#include "io/read_file.h"

#include <fstream>
#include <iterator>
#include <system_error>

#include "softraster/error.h"

namespace softraster {

std::string read_whole_file(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw InputError(path.string() + ": file not found");
    if (std::filesystem::is_directory(path, ec)) throw InputError(path.string() + ": is a directory, not a file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path.string() + ": cannot open file");
    return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace softraster

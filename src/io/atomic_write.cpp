#include "softraster/io/atomic_write.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace softraster {

void write_atomically(const std::filesystem::path& path, const std::function<void(const std::string& tmp)>& write) {
    std::filesystem::path tmp = path;
    tmp += ".tmp";
    std::error_code ec;
    try {
        write(tmp.string());
    } catch (...) {
        std::filesystem::remove(tmp, ec);
        throw;
    }
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::filesystem::remove(tmp, ec);
        throw std::runtime_error(path.string() + ": cannot write (" + ec.message() + ")");
    }
}

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
    write_atomically(path, [&](const std::string& tmp) {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error(path.string() + ": cannot write (" + std::strerror(errno) + ")");
        out.write(bytes.data(), std::streamsize(bytes.size()));
        out.close();
        if (!out) throw std::runtime_error(path.string() + ": write failed");
    });
}

}  // namespace softraster

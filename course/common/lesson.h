// What every lesson program shares: where its pictures go.
#pragma once
#include <cstdio>
#include <filesystem>

namespace course {

// The folder named on the command line (the course target passes the lesson's own folder),
// else the current one; made if missing.
inline std::filesystem::path output_folder(int argc, char** argv) {
    const std::filesystem::path out = argc > 1 ? argv[1] : ".";
    std::filesystem::create_directories(out);
    return out;
}

inline void wrote(const std::filesystem::path& path) { std::printf("wrote %s\n", path.string().c_str()); }

}  // namespace course

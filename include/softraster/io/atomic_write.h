// Files that are whole or absent: written under a temporary name beside the target
// (PATH.tmp), then renamed into place, so that a failure, a crash or a reader at the wrong
// moment never sees a partial file. Errors throw std::runtime_error naming the file.
#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace softraster {

// Runs write(tmp) to fill the temporary file, then renames it to `path`; removes it on failure.
void write_atomically(const std::filesystem::path& path, const std::function<void(const std::string& tmp)>& write);
// `bytes` as the whole content of `path`.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace softraster

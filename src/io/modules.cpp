#include "io/modules.h"

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <dlfcn.h>

namespace softraster {

void* module_entry(const char* file, const char* symbol) {
    std::vector<std::string> dirs;
    if (const char* env = std::getenv("SOFTRASTER_MODULE_DIR")) dirs.emplace_back(env);
    std::error_code ec;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        dirs.push_back(exe.parent_path().string());
        dirs.push_back((exe.parent_path() / SOFTRASTER_MODULE_DIR_FROM_PROGRAM).lexically_normal().string());  // (installed)
    }
    Dl_info self{};
    if (dladdr(reinterpret_cast<const void*>(&module_entry), &self) && self.dli_fname) {
        const std::filesystem::path library = std::filesystem::absolute(self.dli_fname, ec).parent_path();
        dirs.push_back(library.string());
        dirs.push_back((library / "softraster").string());
    }
    dirs.emplace_back();
    for (const std::string& dir : dirs) {
        const std::string path = dir.empty() ? file : dir + "/" + file;
        if (void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL))
            if (void* entry = dlsym(module, symbol)) return entry;
    }
    return nullptr;
}

}  // namespace softraster

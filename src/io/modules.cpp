#include "io/modules.h"

#include "softraster/error.h"

#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include <dlfcn.h>
#include <sys/auxv.h>

namespace softraster {
namespace {

// The running program's file: /proc/self/exe, or where no /proc is mounted (a chroot, a
// minimal container) the name it was started by (AT_EXECFN, which a search of PATH makes a
// full path), with its symbolic links resolved as /proc/self/exe's are. Empty if neither.
std::filesystem::path program_file() {
    std::error_code ec;
    std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) return exe;
    const auto* name = reinterpret_cast<const char*>(getauxval(AT_EXECFN));
    if (!name) return {};
    exe = std::filesystem::weakly_canonical(std::filesystem::absolute(name, ec), ec);
    return ec ? std::filesystem::path() : exe;
}

// The search itself (module_entry).
void* find_module_entry(const char* file, const char* symbol) {
    std::vector<std::string> dirs;
    if (const char* env = std::getenv("SOFTRASTER_MODULE_DIR")) dirs.emplace_back(env);
    std::error_code ec;
    const std::filesystem::path exe = program_file();
    if (!exe.empty()) {
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

}  // namespace

void* module_entry(const char* file, const char* symbol) {
    static std::mutex mutex;
    static std::map<std::pair<std::string, std::string>, void*> found;
    const std::lock_guard lock(mutex);
    const auto [at, first] = found.try_emplace({file, symbol}, nullptr);
    if (first) at->second = find_module_entry(file, symbol);
    return at->second;
}

void* required_module_entry(const char* file, const char* symbol, const std::string& need, const char* hint) {
    if (void* entry = module_entry(file, symbol)) return entry;
    throw InputError(need + " (" + file + "), which was not found; set SOFTRASTER_MODULE_DIR to its folder" + hint);
}

}  // namespace softraster

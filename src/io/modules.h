// The library's modules: the parts that need a dependency of hundreds of shared libraries,
// each in a library of its own that is opened the first time it is needed (dlopen), so
// that the program and the library start without loading them (docs/performance.md
// "Start-up and model files"):
//   libsoftraster_oiio.so    OpenImageIO's pictures (oiio_module.h)
//   libsoftraster_video.so   FFmpeg's videos (video_module.h)
//   libsoftraster_window.so  the program's window, through SDL2 (platform/window_module.h)
#pragma once
#include <string>

namespace softraster {

// The entry point `symbol` of module `file` ("libsoftraster_video.so"), or null where no
// module of that name with that symbol is found. Looked for in $SOFTRASTER_MODULE_DIR,
// beside the program and where it is installed relative to the program, beside the shared
// library and in its softraster/ folder (where `cmake --install` and the packages put it,
// wherever the prefix is), then on the system's library path. Looked for once (found or
// not), opened once, never closed.
void* module_entry(const char* file, const char* symbol);

// The same, or where there is none an InputError: `need` (what needs which module), then
// the module's file and how to point at it, then `hint`.
void* required_module_entry(const char* file, const char* symbol, const std::string& need, const char* hint = "");

}  // namespace softraster

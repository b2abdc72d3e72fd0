// The OpenImageIO decoder lives in a module of its own (libsoftraster_oiio.so, modules.h),
// opened the first time a picture in one of its formats is read. Linking OpenImageIO into the program
// would load Debian's build of it with all its dependencies (about 260 shared libraries:
// OpenCV, GDAL, FFmpeg...) at every start: 0.3 s and 130 MB before main(), for every
// command, including the many that read no SGI, DDS, TIFF, WebP, HDR or EXR picture.
#pragma once
#include <cstddef>
#include <cstdint>

extern "C" {

// What the module's decode function returns: 8-bit RGBA texels, row 0 at the top, in a
// buffer the caller frees with `free`; or `error` set (a one-line message) and no texels.
struct SoftrasterDecoded {
    int width, height;
    uint8_t* rgba;
    char error[512];
};

// Decodes `path` when it is not null, else the `size` bytes at `bytes`, as the format the
// extension `ext` (".dds", ".tif"...) names.
using SoftrasterDecodeFn = void (*)(const char* path, const char* bytes, size_t size, const char* ext,
                                    SoftrasterDecoded* out);
#define SOFTRASTER_OIIO_DECODE "softraster_oiio_decode"
#define SOFTRASTER_OIIO_MODULE "libsoftraster_oiio.so"

}

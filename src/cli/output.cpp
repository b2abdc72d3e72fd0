#include "cli/output.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <system_error>

#include "softraster/error.h"
#include "softraster/io/image_write.h"

namespace softraster::cli {

void check_output_path(const std::filesystem::path& out, std::initializer_list<PictureFormat> allowed) {
    static const char* const names[] = {".png", ".tga", ".ppm", ".exr"};  // by PictureFormat
    const auto format = picture_format(out);
    if (!format || std::find(allowed.begin(), allowed.end(), *format) == allowed.end()) {
        std::string list;
        for (size_t i = 0; i < allowed.size(); ++i)
            list += (i == 0 ? "" : i + 1 == allowed.size() ? " or " : ", ") + std::string(names[size_t(allowed.begin()[i])]);
        throw InputError(out.string() + ": output file must end in " + list);
    }
    const std::filesystem::path dir = out.parent_path();
    std::error_code ec;
    if (!dir.empty() && !std::filesystem::is_directory(dir, ec))
        throw InputError(out.string() + ": output folder '" + dir.string() + "' does not exist");
}

void write_output(const Image& image, const std::filesystem::path& out, std::chrono::duration<double> elapsed, ColorSpace color) {
    try {
        write_picture(image, out, color);
    } catch (const std::runtime_error& e) {
        throw InputError(e.what());
    }
    std::fprintf(stderr, "wrote %s (%dx%d, %.1f ms)\n", out.string().c_str(), image.width, image.height,
                 elapsed.count() * 1000.0);
}

}  // namespace softraster::cli

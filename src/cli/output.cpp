#include "cli/output.h"

#include <cstdio>
#include <system_error>

#include "softraster/error.h"
#include "softraster/io/image_io.h"

namespace softraster::cli {

void check_output_path(const std::filesystem::path& out) {
    if (out.extension() != ".png") throw InputError(out.string() + ": output file must end in .png");
    const std::filesystem::path dir = out.parent_path();
    std::error_code ec;
    if (!dir.empty() && !std::filesystem::is_directory(dir, ec))
        throw InputError(out.string() + ": output folder '" + dir.string() + "' does not exist");
}

void write_output(const Image& image, const std::filesystem::path& out, std::chrono::duration<double> elapsed) {
    try {
        write_png(image, out);
    } catch (const std::runtime_error& e) {
        throw InputError(e.what());
    }
    std::fprintf(stderr, "wrote %s (%dx%d, %.1f ms)\n", out.string().c_str(), image.width, image.height,
                 elapsed.count() * 1000.0);
}

}  // namespace softraster::cli

// softraster: render 3D scenes on the CPU.
#include <malloc.h>

#include "cli/command_line.h"

int main(int argc, char** argv) {
    // Commands that draw many frames (animate, view, thumbnails, bench --orbit) set each one
    // up anew, and a frame's buffers are large: glibc would hand them back to the kernel
    // (mmap/munmap) and take them again, zeroed page by page. Keeping them in the heap lets the
    // next frame reuse the memory (docs/performance.md, "Frames in a row").
    mallopt(M_MMAP_THRESHOLD, 1 << 30);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    return softraster::cli::run_command_line(argc, argv);
}

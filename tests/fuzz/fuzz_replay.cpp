// fuzz_replay CORPUS_DIR: runs every input kept under CORPUS_DIR/<target>/ through its target
// (the inputs fuzzing found crashing, once fixed, and the seeds). A crash fails the test.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_targets.h"

int main(int argc, char** argv) {
    namespace fs = std::filesystem;
    if (argc != 2) {
        std::fprintf(stderr, "usage: fuzz_replay CORPUS_DIR\n");
        return 2;
    }
    size_t inputs = 0;
    for (const std::string& target : softraster::fuzz::target_names()) {
        const fs::path dir = fs::path(argv[1]) / target;
        if (!fs::is_directory(dir)) continue;
        std::vector<fs::path> files;
        for (const auto& e : fs::directory_iterator(dir))
            if (e.is_regular_file()) files.push_back(e.path());
        std::sort(files.begin(), files.end());
        for (const fs::path& f : files) {
            std::ifstream in(f, std::ios::binary);
            const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            std::fprintf(stderr, "%s %s\n", target.c_str(), f.filename().c_str());
            softraster::fuzz::run_target(target, reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
            ++inputs;
        }
    }
    std::printf("%zu inputs replayed without a crash\n", inputs);
    return inputs > 0 ? 0 : 1;
}

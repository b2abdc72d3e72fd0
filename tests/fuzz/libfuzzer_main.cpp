// One libFuzzer program per target (scripts/fuzz.sh builds it with -DFUZZ_TARGET=name).
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    softraster::fuzz::run_target(FUZZ_TARGET, data, size);
    return 0;
}

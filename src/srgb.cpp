// The tables of srgb.h, computed once in double precision.
#include "softraster/srgb.h"

#include <cmath>
#include <limits>

namespace softraster::srgb {
namespace {

double decode_exact(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// The least float at or above x (x > 0).
float float_at_or_above(double x) {
    const float f = float(x);
    return double(f) >= x ? f : std::nextafter(f, std::numeric_limits<float>::infinity());
}

Tables make_tables() {
    Tables t{};
    for (int k = 0; k < 256; ++k) {
        t.decode[size_t(k)] = float(decode_exact(k / 255.0));
        t.decode_fixed[size_t(k)] = uint16_t(std::lround(65280.0 * decode_exact(k / 255.0)));
        t.code_of_fixed[t.decode_fixed[size_t(k)]] = uint8_t(k);
    }
    t.threshold[0] = -std::numeric_limits<float>::infinity();
    t.threshold[256] = std::numeric_limits<float>::infinity();
    for (int k = 1; k < 256; ++k) t.threshold[size_t(k)] = float_at_or_above(decode_exact((k - 0.5) / 255.0));
    // Each interval's first float, the number of thresholds it reaches, and the threshold
    // inside it, if any.
    int k = 0;
    for (int b = 0; b < Tables::kBuckets; ++b) {
        const uint32_t first = uint32_t(Tables::kFirstBucket + b) << 16;
        while (k < 255 && std::bit_cast<float>(first) >= t.threshold[size_t(k) + 1]) ++k;
        const uint32_t next = std::bit_cast<uint32_t>(t.threshold[size_t(k) + 1]);  // (+inf past 255)
        const int low = k < 255 && (next >> 16) == (first >> 16) ? int(next & 0xffffu) : Tables::kNoThreshold;
        t.bucket[size_t(b)] = (k << 17) | low;
    }
    return t;
}

}  // namespace

float decode_value(double c) { return float(decode_exact(c)); }

const Tables& tables() {
    static const Tables t = make_tables();
    return t;
}

}  // namespace softraster::srgb

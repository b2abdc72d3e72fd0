// Tests of the eight-lane helpers the per-pixel code is built on (pipeline/simd.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "softraster/pipeline/simd.h"

using namespace softraster;
using namespace softraster::simd;

namespace {

i8 mask_of(unsigned bitset) {
    i8 m{};
    for (int l = 0; l < kLanes; ++l) m[l] = (bitset >> l) & 1u ? -1 : 0;
    return m;
}

TEST(Simd, BitsAndAnyReadEveryLaneMask) {
    for (unsigned b = 0; b < 256; ++b) {
        EXPECT_EQ(bits(mask_of(b)), b);
        EXPECT_EQ(any(mask_of(b)), b != 0);
    }
    // as the comparisons that make masks give them
    const i8 x = {5, -1, 7, 0, 3, 9, -4, 2};
    EXPECT_EQ(bits(x > 2), 0b00110101u);
    EXPECT_FALSE(any(x > 100));
}

TEST(Simd, GroupsCoverASpanOnceAlignedToEight) {
    for (int begin = 0; begin < 24; ++begin)
        for (int end = begin + 1; end <= 40; ++end) {
            std::vector<int> hits(48, 0);
            for_each_group(begin, end, [&](int x, i8 lanes) {
                EXPECT_EQ(x % kLanes, 0);
                for (int l = 0; l < kLanes; ++l)
                    if (lanes[l]) ++hits[size_t(x + l)];
            });
            for (int x = 0; x < 48; ++x) EXPECT_EQ(hits[size_t(x)], x >= begin && x < end ? 1 : 0) << begin << " " << end;
        }
}

TEST(Simd, LoadAndStoreStopAtTheEndOfTheRow) {
    std::array<float, 16> row{};
    for (size_t i = 0; i < row.size(); ++i) row[i] = float(i);
    const int width = 11;  // the group at x = 8 has three pixels in the row
    const f8 v = load_group<f8>(row.data(), 8, width);
    for (int l = 0; l < kLanes; ++l) EXPECT_EQ(v[l], l < 3 ? float(8 + l) : 0.0f);
    store_group(row.data(), 8, width, splat(-1.0f));
    for (size_t i = 0; i < row.size(); ++i) EXPECT_EQ(row[i], i >= 8 && i < 11 ? -1.0f : float(i));
}

// Two rows of four (a 4x2 block): lanes 0-3 from the first, 4-7 from the second, and back,
// nothing else touched.
TEST(Simd, HalvesLoadAndStoreTwoRowsOfFour) {
    std::array<float, 24> rows{};
    for (size_t i = 0; i < rows.size(); ++i) rows[i] = float(i);
    const int width = 10;
    const f8 v = load_halves(rows.data() + 3, rows.data() + 3 + width);
    for (int l = 0; l < kLanes; ++l) EXPECT_EQ(v[l], float(l < 4 ? 3 + l : 3 + width + l - 4)) << "lane " << l;
    store_halves(rows.data() + 3, rows.data() + 3 + width, to_float(kLaneIndex) + 100.0f);
    for (size_t i = 0; i < rows.size(); ++i) {
        const int at = int(i) - 3;
        const bool first = at >= 0 && at < 4, second = at >= width && at < width + 4;
        EXPECT_EQ(rows[i], first ? float(100 + at) : second ? float(100 + 4 + at - width) : float(i)) << "value " << i;
    }
}

// Bytes (a stencil row) widened into lanes and narrowed back, each lane's low byte only, for
// every number of bytes left in the row.
TEST(Simd, BytesWidenAndNarrowStoppingAtTheEndOfTheRow) {
    for (int left = 1; left <= 9; ++left) {
        std::array<uint8_t, 24> row{};
        for (size_t i = 0; i < row.size(); ++i) row[i] = uint8_t(250 - 13 * i);  // (high bits set in some)
        const int x = 8, width = x + left;
        const i8 v = load_bytes(row.data(), x, width);
        for (int l = 0; l < kLanes; ++l) EXPECT_EQ(v[l], l < left ? int(row[size_t(x + l)]) : 0) << left << " left, lane " << l;
        const std::array<uint8_t, 24> before = row;
        store_bytes(row.data(), x, width, kLaneIndex * 0x101 + 0x7f00 + 3);  // low bytes 3..10, the rest dropped
        for (size_t i = 0; i < row.size(); ++i) {
            const bool written = int(i) >= x && int(i) < std::min(width, x + kLanes);
            EXPECT_EQ(row[i], written ? uint8_t(int(i) - x + 3) : before[i]) << left << " left, byte " << i;
        }
    }
}

}  // namespace

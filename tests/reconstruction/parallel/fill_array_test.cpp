#include "reconstruction/parallel/fill_array.h"

#include <cstdint>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "reconstruction/parallel/prefault.h"
#include "reconstruction/section/section_frame.h"

using namespace caliper3d::reconstruction;

TEST(FillArrayTest, ElementsSetByWorkersAreCopiedAndMoved) {
    FillArray<SectionFrame> frames(3);
    ASSERT_EQ(frames.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) frames.set(i, frameFromPadAzimuth(10.0 * i, 20.0, 30.0));
    const FillArray<SectionFrame> copy = frames;
    FillArray<SectionFrame> moved = std::move(frames);
    EXPECT_EQ(frames.size(), 0u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(copy[i].arm1, frameFromPadAzimuth(10.0 * i, 20.0, 30.0).arm1);
        EXPECT_EQ(moved[i].side, copy[i].side);
    }
    moved = FillArray<SectionFrame>();
    EXPECT_EQ(moved.size(), 0u);
}

TEST(PrefaultTest, ChangesNoByteOfTheBuffer) {
    for (int threads : {1, 2, 3}) {
        std::vector<std::uint32_t> data(5'000'003);
        std::iota(data.begin(), data.end(), 7u);
        prefaultPages(data.data() + 1, (data.size() - 2) * sizeof(std::uint32_t), threads);
        prefaultPages(data.data(), 0, threads);
        for (std::size_t i = 0; i < data.size(); ++i) ASSERT_EQ(data[i], 7u + i);
    }
}

#include "reconstruction/segment_length.h"

#include <vector>

#include <gtest/gtest.h>

using namespace caliper3d::reconstruction;

namespace {

std::vector<double> rows(std::size_t count, double step_m, double top_m = 100.0) {
    std::vector<double> depth;
    for (std::size_t i = 0; i < count; ++i)
        depth.push_back(top_m + static_cast<double>(i) * step_m);
    return depth;
}

}  // namespace

TEST(SegmentLengthTest, OneMetreForFineLogsAndAHundredRowsForSparseOnes) {
    EXPECT_EQ(autoSegmentLength(rows(5000, 0.0025)), 1.0);  // imager and caliper logs
    EXPECT_EQ(autoSegmentLength(rows(5000, 0.01)), 1.0);
    EXPECT_EQ(autoSegmentLength(rows(5000, 0.05)), 5.0);
    EXPECT_EQ(autoSegmentLength(rows(5000, 0.1)), 10.0);
    EXPECT_EQ(autoSegmentLength(rows(5000, 0.1524)), 16.0);  // half a foot: 15.24 m, rounded up
    EXPECT_EQ(autoSegmentLength(rows(1, 0.1)), 1.0);
    EXPECT_EQ(autoSegmentLength({}), 1.0);
}

TEST(SegmentLengthTest, TheMedianStepOfTheFirstRowsDecides) {
    // A few gaps do not move the median; rows past the first kSegmentStepRows are not read,
    // so a streamed load decides as soon as it has them, as the whole well does.
    std::vector<double> depth = rows(kSegmentStepRows, 0.1);
    depth[10] += 0.05;
    depth[500] += 0.07;
    for (std::size_t i = 0; i < 3000; ++i) depth.push_back(depth.back() + 0.0025);
    EXPECT_EQ(autoSegmentLength(depth), 10.0);
}

#include "app/desktop/trace_decimation.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

using namespace caliper3d;

namespace {

// A 4 km log sampled every centimetre (400,000 rows), from 100 m.
std::vector<double> depths(std::size_t rows) {
    std::vector<double> depth(rows);
    for (std::size_t i = 0; i < rows; ++i) depth[i] = 100.0 + 0.01 * double(i);
    return depth;
}

std::size_t pointCount(const std::vector<app::TraceRun>& runs) {
    std::size_t n = 0;
    for (const auto& run : runs) n += run.size();
    return n;
}

}  // namespace

TEST(TraceDecimationTest, KeepsEachPixelsLowestAndHighestRowAndTheSpikes) {
    const std::size_t rows = 400000;
    const std::vector<double> depth = depths(rows);
    std::vector<double> value(rows);
    for (std::size_t i = 0; i < rows; ++i) value[i] = 216.0 + 2.0 * std::sin(0.001 * double(i));
    value[123457] = 290.0;  // a one-row spike (a washed-out centimetre)
    value[300001] = 150.0;  // and a one-row dip
    const int buckets = 800;
    const auto runs = app::decimateTrace(depth, value, depth.front(), depth.back(), buckets);
    ASSERT_EQ(runs.size(), 1u);
    // At most two points a pixel (the last row, at the bottom edge, opens a bucket of its
    // own), and the run's first and last rows.
    EXPECT_LE(pointCount(runs), std::size_t(2 * (buckets + 1) + 2));
    EXPECT_GE(pointCount(runs), std::size_t(buckets));
    const auto& run = runs.front();
    const auto spike =
        std::find_if(run.begin(), run.end(), [](auto p) { return p.value == 290.0; });
    ASSERT_NE(spike, run.end());
    EXPECT_DOUBLE_EQ(spike->depth_m, depth[123457]);
    const auto dip = std::find_if(run.begin(), run.end(), [](auto p) { return p.value == 150.0; });
    ASSERT_NE(dip, run.end());
    EXPECT_DOUBLE_EQ(dip->depth_m, depth[300001]);
    // Every point is a row of the log, in depth order.
    for (std::size_t i = 1; i < run.size(); ++i) EXPECT_LT(run[i - 1].depth_m, run[i].depth_m);
}

TEST(TraceDecimationTest, AMonotonicCurveKeepsTheFirstAndLastRowOfEachPixel) {
    const std::vector<double> depth = depths(1000);  // 100 to 109.99 m
    const std::vector<double> value(depth);          // value = depth: lowest first
    // Ten pixels of one metre: rows 100.00 and 100.99, 101.00 and 101.99...
    const auto runs = app::decimateTrace(depth, value, 100.0, 110.0, 10);
    ASSERT_EQ(runs.size(), 1u);
    ASSERT_EQ(runs[0].size(), 20u);
    for (int b = 0; b < 10; ++b) {
        EXPECT_NEAR(runs[0][2 * b].depth_m, 100.0 + b, 1e-9);
        EXPECT_NEAR(runs[0][2 * b + 1].depth_m, 100.99 + b, 1e-9);
    }
}

TEST(TraceDecimationTest, RowsWithoutDataSplitTheCurveHoweverShortTheGap) {
    const std::vector<double> depth = depths(10000);  // 100 to 199.99 m
    std::vector<double> value(depth.size(), 220.0);
    for (std::size_t i = 2000; i < 2200; ++i) value[i] = std::nan("");  // 120.00 - 121.99 m
    value[7000] = std::nan("");  // one row at 170 m, far less than a pixel of 1 m
    const auto runs = app::decimateTrace(depth, value, 100.0, 200.0, 100);
    ASSERT_EQ(runs.size(), 3u);
    EXPECT_NEAR(runs[0].back().depth_m, 119.99, 1e-9);
    EXPECT_NEAR(runs[1].front().depth_m, 122.0, 1e-9);
    EXPECT_NEAR(runs[1].back().depth_m, 169.99, 1e-9);
    EXPECT_NEAR(runs[2].front().depth_m, 170.01, 1e-9);
    for (const auto& run : runs)
        for (const auto& p : run) EXPECT_FALSE(p.depth_m >= 120.0 && p.depth_m < 122.0);
    // All rows without data: nothing to draw.
    EXPECT_TRUE(app::decimateTrace(depth, std::vector<double>(depth.size(), std::nan("")), 100.0,
                                   200.0, 100)
                    .empty());
}

TEST(TraceDecimationTest, AWindowKeepsItsRowsAndOneBeyondEachEnd) {
    const std::vector<double> depth = depths(10000);
    std::vector<double> value(depth.size());
    for (std::size_t i = 0; i < value.size(); ++i) value[i] = double(i % 7);
    // Zoomed in past the rows (more pixels than rows): every row is kept as it is.
    const auto runs = app::decimateTrace(depth, value, 150.0, 150.5, 600);
    ASSERT_EQ(runs.size(), 1u);
    ASSERT_EQ(runs[0].size(), 53u);  // 150.00 .. 150.50, and 149.99 and 150.51
    EXPECT_NEAR(runs[0].front().depth_m, 149.99, 1e-9);
    EXPECT_NEAR(runs[0].back().depth_m, 150.51, 1e-9);
    for (const auto& p : runs[0])
        EXPECT_DOUBLE_EQ(p.value, double(std::lround((p.depth_m - 100.0) / 0.01) % 7));
    EXPECT_TRUE(app::decimateTrace(depth, value, 150.0, 150.0, 600).empty());
    EXPECT_TRUE(app::decimateTrace({}, {}, 0.0, 1.0, 10).empty());
}

TEST(TraceDecimationTest, ReadsACurveInPlaceFromAFieldOfRecords) {
    // Records as the analysis keeps its sections: the depth and two values side by side.
    struct Row {
        double depth_m;
        double dmin_mm;
        int code;
        double dmax_mm;
    };
    std::vector<Row> rows(10000);
    for (std::size_t i = 0; i < rows.size(); ++i)
        rows[i] = {100.0 + 0.01 * double(i), double(i % 7), int(i), 300.0 + double(i % 5)};
    rows[4000].dmax_mm = std::nan("");  // a row without data splits the curve
    const app::RowCurve depth = app::RowCurve::field(rows.data(), &Row::depth_m, rows.size());
    const app::RowCurve dmax = app::RowCurve::field(rows.data(), &Row::dmax_mm, rows.size());
    ASSERT_EQ(depth.size(), rows.size());
    EXPECT_EQ(depth.front(), 100.0);
    EXPECT_DOUBLE_EQ(depth.back(), 199.99);
    EXPECT_EQ(dmax[4], 304.0);
    // Zoomed in: every row between 139.955 and 140.045 and one beyond each end, the one
    // without data (140.00) leaving two runs.
    const auto runs = app::decimateTrace(depth, dmax, 139.955, 140.045, 600);
    ASSERT_EQ(runs.size(), 2u);
    EXPECT_EQ(runs[0].size(), 5u);  // 139.95 .. 139.99
    EXPECT_EQ(runs[1].size(), 5u);  // 140.01 .. 140.05
    EXPECT_NEAR(runs[0].front().depth_m, 139.95, 1e-9);
    EXPECT_NEAR(runs[0].back().depth_m, 139.99, 1e-9);
    EXPECT_NEAR(runs[1].front().depth_m, 140.01, 1e-9);
    EXPECT_NEAR(runs[1].back().depth_m, 140.05, 1e-9);
    for (const auto& run : runs)
        for (const auto& p : run)
            EXPECT_EQ(p.value, 300.0 + double(std::lround((p.depth_m - 100.0) / 0.01) % 5));
    // The whole log, thinned: the same points as from copies of the two curves.
    std::vector<double> depthCopy, dmaxCopy;
    for (const Row& r : rows) {
        depthCopy.push_back(r.depth_m);
        dmaxCopy.push_back(r.dmax_mm);
    }
    const auto inPlace = app::decimateTrace(depth, dmax, 100.0, 199.99, 300);
    const auto copied = app::decimateTrace(depthCopy, dmaxCopy, 100.0, 199.99, 300);
    ASSERT_EQ(inPlace.size(), copied.size());
    for (std::size_t k = 0; k < inPlace.size(); ++k) {
        ASSERT_EQ(inPlace[k].size(), copied[k].size());
        for (std::size_t j = 0; j < inPlace[k].size(); ++j) {
            EXPECT_EQ(inPlace[k][j].depth_m, copied[k][j].depth_m);
            EXPECT_EQ(inPlace[k][j].value, copied[k][j].value);
        }
    }
}

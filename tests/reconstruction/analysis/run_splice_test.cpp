// Splicing runs of one well: known shifts, a join in the overlap, a repeat over a bad interval.
#include "reconstruction/analysis/run_splice.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "io/casing_program.h"
#include "reconstruction/synthetic/synthetic_well.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {

// A vertical run every 5 cm from `top` over `length` of its counter, which reads `offset`
// deeper than the hole; a washout of 265.9 mm at 70-72 m of the hole.
io::SectionTable run(double top, double length, double offset) {
    SyntheticWellSpec spec;
    spec.top_m = top;
    spec.length_m = length;
    spec.step_m = 0.05;
    spec.depthOffset_m = offset;
    spec.features.push_back({SyntheticFeature::Kind::Washout, 70.0, 72.0, 265.9, 265.9, 0.0, 0.0});
    return makeSyntheticWell(spec);
}

DepthMapping shift(double s) {
    DepthMapping m;
    m.shift_m = s;
    return m;
}

const std::vector<double>& runCurve(const io::SectionTable& t) {
    return t.extraCurves.back().values;
}

}  // namespace

TEST(RunSpliceTest, OverlappingRunsJoinInTheMiddleWithOneStepAndFeaturesAtTheirDepths) {
    const io::SectionTable upper = run(0.0, 60.0, 0.0);
    const io::SectionTable lower = run(40.0, 60.0, 0.3);  // the hole at 39.7-99.7 m
    const SplicedLog log = spliceRuns({&upper, &lower}, {shift(0.3)});
    ASSERT_EQ(log.joins.size(), 1u);
    EXPECT_NEAR(log.joins[0].overlapTop_m, 39.7, 1e-9);
    EXPECT_NEAR(log.joins[0].overlapBottom_m, 60.0, 1e-9);
    EXPECT_NEAR(log.joins[0].at_m, 49.85, 1e-9);
    const io::SectionTable& t = log.table;
    ASSERT_EQ(t.rowCount(), 1995u);
    for (std::size_t i = 1; i < t.rowCount(); ++i)
        ASSERT_NEAR(t.depth_m[i] - t.depth_m[i - 1], 0.05, 1e-9) << t.depth_m[i];
    EXPECT_EQ(t.extraCurves.back().mnemonic, "RUN");
    for (std::size_t i = 0; i < t.rowCount(); ++i) {
        EXPECT_EQ(runCurve(t)[i], t.depth_m[i] < 49.85 - 1e-6 ? 1.0 : 2.0) << t.depth_m[i];
        EXPECT_EQ(t.bitSize_mm[i], 215.9);
        if (t.depth_m[i] > 70.01 && t.depth_m[i] < 71.99) {
            EXPECT_NEAR(t.radii(i)[0], 132.95, 1e-9);
        }
    }
}

TEST(RunSpliceTest, EachRunKeepsItsCasingAndBitSizeOverItsOwnRows) {
    // Run 1 drilled 12 1/4 in below 13 3/8 in casing to 10.01 m; run 2 8 1/2 in below 9 5/8
    // in casing set to 55.01 m of its counter (54.71 m of the hole, run 1's open hole). Joined
    // at 49.85 m: run 1's rows keep their open hole below 10 m, run 2's are cased to 54.71 m.
    io::SectionTable upper = run(0.0, 60.0, 0.0);
    io::SectionTable lower = run(40.0, 60.0, 0.3);
    std::fill(upper.bitSize_mm.begin(), upper.bitSize_mm.end(), 311.15);
    io::CasingString surface, intermediate;
    surface.bottom_m = 10.01;
    surface.size_mm = 339.725;
    surface.innerDiameter_mm = 315.32;
    intermediate.bottom_m = 55.01;
    intermediate.size_mm = 244.475;
    intermediate.innerDiameter_mm = 220.5;
    upper.casing = {surface};
    lower.casing = {intermediate};
    const SplicedLog log = spliceRuns({&upper, &lower}, {shift(0.3)});
    const io::SectionTable& t = log.table;
    ASSERT_EQ(t.casing.size(), 2u);
    EXPECT_EQ(t.casing[0].size_mm, surface.size_mm);
    EXPECT_NEAR(t.casing[0].bottom_m, 10.01, 1e-9);
    EXPECT_NEAR(t.casing[0].appliesFrom_m, 0.0, 1e-9);
    EXPECT_NEAR(t.casing[0].appliesTo_m, 49.825, 1e-9);  // midway to run 2's first row
    EXPECT_EQ(t.casing[1].size_mm, intermediate.size_mm);
    EXPECT_NEAR(t.casing[1].bottom_m, 54.71, 1e-9);  // in the log's depths
    EXPECT_NEAR(t.casing[1].appliesFrom_m, 49.825, 1e-9);
    EXPECT_NEAR(t.casing[1].appliesTo_m, 99.7, 1e-9);
    std::size_t cased1 = 0, open1 = 0, cased2 = 0, open2 = 0;
    for (std::size_t i = 0; i < t.rowCount(); ++i) {
        const double md = t.depth_m[i];
        const bool first = runCurve(t)[i] == 1.0;
        EXPECT_EQ(t.bitSize_mm[i], first ? 311.15 : 215.9) << md;
        const io::CasingString* c = io::casingAt(t.casing, md);
        if (first && md < 10.01) {
            ASSERT_NE(c, nullptr) << md;
            EXPECT_EQ(c->size_mm, surface.size_mm) << md;
            ++cased1;
        } else if (!first && md < 54.71) {
            ASSERT_NE(c, nullptr) << md;
            EXPECT_EQ(c->size_mm, intermediate.size_mm) << md;
            ++cased2;
        } else {
            EXPECT_EQ(c, nullptr) << md;
            ++(first ? open1 : open2);
        }
    }
    EXPECT_EQ(cased1, 201u);  // 0-10 m
    EXPECT_EQ(open1, 796u);   // 10.05-49.80 m
    EXPECT_EQ(cased2, 98u);   // 49.85-54.70 m
    EXPECT_EQ(open2, 900u);   // 54.75-99.70 m
}

TEST(RunSpliceTest, AShiftOffTheStepIsRoundedToWholeStepsUnlessAskedExact) {
    const io::SectionTable upper = run(0.0, 60.0, 0.0);
    const io::SectionTable lower = run(40.0, 60.0, 0.3);
    const SplicedLog rounded = spliceRuns({&upper, &lower}, {shift(0.3012)});
    EXPECT_NEAR(rounded.joins[0].appliedShift_m, 0.3, 1e-12);
    SpliceOptions exact;
    exact.exactShift = true;
    const SplicedLog kept = spliceRuns({&upper, &lower}, {shift(0.3012)}, exact);
    EXPECT_NEAR(kept.joins[0].appliedShift_m, 0.3012, 1e-12);
    EXPECT_NEAR(kept.table.depth_m.back(), 100.0 - 0.3012, 1e-9);
}

TEST(RunSpliceTest, ARepeatOverABadIntervalReplacesThatIntervalOnly) {
    const io::SectionTable main = run(0.0, 100.0, 0.0);
    const io::SectionTable repeat = run(60.0, 20.0, -0.5);  // the hole at 60.5-80.5 m
    const SplicedLog log = spliceRuns({&main, &repeat}, {shift(-0.5)});
    EXPECT_NEAR(log.joins[0].at_m, 60.5, 1e-9);
    EXPECT_NEAR(log.joins[0].until_m, 80.5, 1e-9);
    const io::SectionTable& t = log.table;
    ASSERT_EQ(t.rowCount(), 2001u);
    for (std::size_t i = 0; i < t.rowCount(); ++i) {
        if (i > 0) {
            ASSERT_NEAR(t.depth_m[i] - t.depth_m[i - 1], 0.05, 1e-9) << t.depth_m[i];
        }
        const bool repeated = t.depth_m[i] > 60.5 - 1e-6 && t.depth_m[i] < 80.5 + 1e-6;
        EXPECT_EQ(runCurve(t)[i], repeated ? 2.0 : 1.0) << t.depth_m[i];
    }
}

TEST(RunSpliceTest, BadJoinsAreRefused) {
    const io::SectionTable upper = run(0.0, 60.0, 0.0);
    const io::SectionTable lower = run(40.0, 60.0, 0.3);
    SpliceOptions outside;
    outside.at_m = {30.0};
    EXPECT_THROW(spliceRuns({&upper, &lower}, {shift(0.3)}, outside), std::runtime_error);
    const io::SectionTable apart = run(200.0, 60.0, 0.0);
    EXPECT_THROW(spliceRuns({&upper, &apart}, {shift(0.0)}), std::runtime_error);
    EXPECT_THROW(spliceRuns({&lower, &upper}, {shift(-0.3)}), std::runtime_error);  // order
    io::SectionTable four = lower;
    four.armCount = 4;
    four.radius_mm.resize(four.rowCount() * 4);
    EXPECT_THROW(spliceRuns({&upper, &four}, {shift(0.3)}), std::runtime_error);
}

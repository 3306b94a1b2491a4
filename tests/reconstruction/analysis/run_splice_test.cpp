// Splicing runs of one well: known shifts, a join in the overlap, a repeat over a bad interval.
#include "reconstruction/analysis/run_splice.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

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

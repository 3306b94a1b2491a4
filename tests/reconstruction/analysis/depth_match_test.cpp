// Depth matching of two runs: known shifts and stretches of one gamma-ray log.
#include "reconstruction/analysis/depth_match.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "reconstruction/synthetic/synthetic_well.h"

using namespace caliper3d::reconstruction;

namespace {

// The formation's gamma ray as a run reads it: sampled every `step` from `top` over `length`,
// the counter reading depth d where the formation is at d - shift(d).
template <class Shift>
DepthCurve gammaRun(double top, double length, double step, Shift shift) {
    DepthCurve c;
    const auto rows = static_cast<int>(std::floor(length / step + 1e-9)) + 1;
    for (int i = 0; i < rows; ++i) {
        const double d = top + i * step;
        c.depth_m.push_back(d);
        c.values.push_back(syntheticGammaRay_api(d - shift(d)));
    }
    return c;
}

DepthCurve gammaRun(double top, double length, double step, double shift = 0.0) {
    return gammaRun(top, length, step, [shift](double) { return shift; });
}

}  // namespace

TEST(DepthMatchTest, FindsAShiftOfWholeStepsExactly) {
    const DepthCurve run1 = gammaRun(0.0, 300.0, 0.05);
    const DepthCurve run2 = gammaRun(0.0, 300.0, 0.05, 0.35);
    const DepthMatch m = matchDepths(run1, run2);
    EXPECT_NEAR(m.shift_m, 0.35, 1e-3);
    EXPECT_GT(m.correlation, 0.999);
    EXPECT_GT(m.samples, 5900u);
}

TEST(DepthMatchTest, RefinesAShiftBelowTheSamplingStep) {
    // 0.333 m is 3.33 steps of 0.1 m: the grid alone could say 0.3 or 0.4.
    const DepthCurve run1 = gammaRun(100.0, 200.0, 0.1);
    const DepthCurve run2 = gammaRun(90.0, 220.0, 0.1, 0.333);
    const DepthMatch m = matchDepths(run1, run2);
    EXPECT_NEAR(m.shift_m, 0.333, 0.01);
    EXPECT_GT(m.correlation, 0.99);
}

TEST(DepthMatchTest, FindsAShallowerSecondRunAndOneSampledDifferently) {
    // The second run reads 1.27 m shallower, every 0.1524 m (half a foot) against 0.05 m.
    const DepthCurve run1 = gammaRun(0.0, 200.0, 0.05);
    const DepthCurve run2 = gammaRun(5.0, 150.0, 0.1524, -1.27);
    const DepthMatch m = matchDepths(run1, run2);
    EXPECT_NEAR(m.shift_m, -1.27, 0.01);
}

TEST(DepthMatchTest, AShiftBeyondTheSearchWindowIsNotFound) {
    // 3 m apart, searched within 2 m: the best lag in the window is not the truth, and the
    // correlation says so.
    const DepthCurve run1 = gammaRun(0.0, 200.0, 0.05);
    const DepthCurve run2 = gammaRun(0.0, 200.0, 0.05, 3.0);
    const DepthMatch narrow = matchDepths(run1, run2);
    EXPECT_GT(std::abs(narrow.shift_m - 3.0), 0.9);
    EXPECT_LT(narrow.correlation, 0.8);
    DepthMatchOptions wide;
    wide.maxShift_m = 4.0;
    EXPECT_NEAR(matchDepths(run1, run2, wide).shift_m, 3.0, 0.01);
}

TEST(DepthMatchTest, RunsThatDoNotOverlapAreAnError) {
    const DepthCurve run1 = gammaRun(0.0, 100.0, 0.05);
    const DepthCurve run2 = gammaRun(200.0, 100.0, 0.05);
    try {
        (void)matchDepths(run1, run2);
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("do not overlap"), std::string::npos) << e.what();
    }
}

TEST(DepthMatchTest, AFlatCurveCannotBeMatched) {
    DepthCurve run1 = gammaRun(0.0, 100.0, 0.05);
    DepthCurve run2 = run1;
    for (double& v : run2.values) v = 80.0;
    EXPECT_THROW((void)matchDepths(run1, run2), std::runtime_error);
}

TEST(DepthMatchTest, ACounterThatStretchesIsFittedBetweenTwoTiePoints) {
    // Run 2's counter gains 1 mm per metre on run 1's from 0.2 m at the top: at 900 m it reads
    // 0.2 + 0.9 = 1.1 m deeper.
    const auto drift = [](double d2) { return (0.2 + 0.001 * d2) / 1.001; };
    const DepthCurve run1 = gammaRun(0.0, 1000.0, 0.1);
    const DepthCurve run2 = gammaRun(0.0, 1002.0, 0.1, drift);
    const DepthMapping mapping = fitDepthMapping(run1, run2);
    ASSERT_EQ(mapping.ties.size(), 2u);
    EXPECT_NEAR(mapping.stretch, 0.001, 1e-4);
    EXPECT_NEAR(mapping.toRun2(900.0), 900.0 + 0.2 + 0.9, 0.02);
    EXPECT_NEAR(mapping.toRun2(100.0), 100.0 + 0.2 + 0.1, 0.02);
    EXPECT_NEAR(mapping.toRun1(mapping.toRun2(512.3)), 512.3, 1e-9);
}

TEST(DepthMatchTest, CountersThatAgreeGiveNoStretch) {
    const DepthCurve run1 = gammaRun(0.0, 600.0, 0.1);
    const DepthCurve run2 = gammaRun(0.0, 600.0, 0.1, 0.5);
    const DepthMapping mapping = fitDepthMapping(run1, run2);
    ASSERT_EQ(mapping.ties.size(), 2u);  // measured, and found to agree
    EXPECT_EQ(mapping.stretch, 0.0);
    EXPECT_NEAR(mapping.shift_m, 0.5, 0.01);
    for (const DepthTie& t : mapping.ties) EXPECT_NEAR(t.match.shift_m, 0.5, 0.01);
}

TEST(DepthMatchTest, ThreadsGiveTheSameMatchBitForBit) {
    // The lags are correlated in blocks on the workers, and the tie windows side by side: each
    // sum is the same sum in the same order, so the mapping is the one-thread mapping exactly.
    const auto drift = [](double d2) { return (0.2 + 0.001 * d2) / 1.001; };
    const DepthCurve run1 = gammaRun(0.0, 1000.0, 0.1);
    const DepthCurve run2 = gammaRun(0.0, 1002.0, 0.1, drift);
    DepthMappingOptions options;
    const DepthMapping one = fitDepthMapping(run1, run2, options);
    ASSERT_EQ(one.ties.size(), 2u);
    for (const int threads : {2, 3, 8}) {
        options.match.threads = threads;
        const DepthMapping many = fitDepthMapping(run1, run2, options);
        EXPECT_EQ(many.shift_m, one.shift_m) << threads;
        EXPECT_EQ(many.stretch, one.stretch) << threads;
        EXPECT_EQ(many.match.correlation, one.match.correlation) << threads;
        ASSERT_EQ(many.ties.size(), one.ties.size()) << threads;
        for (std::size_t k = 0; k < one.ties.size(); ++k) {
            EXPECT_EQ(many.ties[k].md1_m, one.ties[k].md1_m) << threads;
            EXPECT_EQ(many.ties[k].match.shift_m, one.ties[k].match.shift_m) << threads;
            EXPECT_EQ(many.ties[k].match.correlation, one.ties[k].match.correlation) << threads;
        }
    }
}

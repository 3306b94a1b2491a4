#include "reconstruction/synthetic/synthetic_well.h"

#include <algorithm>
#include <string>

#include <gtest/gtest.h>

using namespace caliper3d::reconstruction;

TEST(SyntheticWellTest, ExampleProfileHasKnownFeatures) {
    const SyntheticWellSpec spec = syntheticProfile("example", 300.0, 0.05);
    const auto t = makeSyntheticWell(spec);
    ASSERT_EQ(t.rowCount(), 6001u);
    ASSERT_EQ(t.armCount, 6);
    auto rowAt = [&](double md) { return static_cast<std::size_t>(md / 0.05 + 0.5); };
    // Gauge hole above the breakout.
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(t.radii(rowAt(10.0))[k], 215.9 / 2, 1e-9);
    // Washout: every arm reads the washed-out radius.
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(t.radii(rowAt(155.0))[k], 265.9 / 2, 1e-9);
    // Breakout: the radii span the ellipse's semi-axes range.
    const double* r = t.radii(rowAt(70.0));
    const auto [mn, mx] = std::minmax_element(r, r + 6);
    EXPECT_GE(*mn, 217.9 / 2 - 1e-9);
    EXPECT_LE(*mx, 245.9 / 2 + 1e-9);
    EXPECT_GT(*mx - *mn, 5.0);
    // Build section: vertical to 100 m, 3 deg/30 m after.
    EXPECT_DOUBLE_EQ(t.devi_deg[rowAt(50.0)], 0.0);
    EXPECT_NEAR(t.devi_deg[rowAt(200.0)], 10.0, 1e-9);
    EXPECT_NEAR(t.devi_deg[rowAt(290.0)], 15.0, 1e-9);
}

TEST(SyntheticWellTest, LongWellsLevelOffAtHorizontalInsteadOfTurningBack) {
    // At 4 km the example builds 3 deg/30 m over 2 km: 200 degrees uncapped.
    for (const std::string name : {"example", "build", "keyseat"}) {
        const SyntheticWellSpec spec = syntheticProfile(name, 4000.0, 1.0);
        const caliper3d::io::SectionTable t = makeSyntheticWell(spec);
        const double deepest = *std::max_element(t.devi_deg.begin(), t.devi_deg.end());
        EXPECT_DOUBLE_EQ(deepest, 90.0) << name;
        EXPECT_DOUBLE_EQ(t.devi_deg.back(), 90.0) << name;
    }
    // A short example keeps its 15 degree build.
    const caliper3d::io::SectionTable shortWell =
        makeSyntheticWell(syntheticProfile("example", 300.0, 1.0));
    EXPECT_NEAR(*std::max_element(shortWell.devi_deg.begin(), shortWell.devi_deg.end()), 15.0,
                1e-9);
}

TEST(SyntheticWellTest, EllipseRadiusAtAxes) {
    EXPECT_DOUBLE_EQ(ellipseRadius_mm(240, 200, 0), 120);
    EXPECT_NEAR(ellipseRadius_mm(240, 200, 90), 100, 1e-12);
    EXPECT_NEAR(ellipseRadius_mm(240, 200, 180), 120, 1e-12);
}

TEST(SyntheticWellTest, RejectsImpossibleSpecs) {
    EXPECT_THROW(syntheticProfile("nonsense", 10, 1), std::invalid_argument);
    SyntheticWellSpec spec;
    spec.step_m = 0;
    EXPECT_THROW(makeSyntheticWell(spec), std::invalid_argument);
}

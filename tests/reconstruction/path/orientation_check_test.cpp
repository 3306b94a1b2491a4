#include "reconstruction/path/orientation_check.h"

#include <cmath>

#include <gtest/gtest.h>

#include "reconstruction/synthetic/synthetic_well.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

TEST(OrientationCheckTest, SyntheticPadAzimuthAgreesWithHoleAzimuthAndRelativeBearing) {
    const io::SectionTable t = makeSyntheticWell(syntheticProfile("build", 300.0, 0.5));
    const OrientationOffset o = padAzimuthOffset(t);
    EXPECT_GT(o.samples, 400u);
    EXPECT_NEAR(o.mean_deg, 0.0, 1e-6);
    EXPECT_NEAR(o.sd_deg, 0.0, 1e-4);
}

TEST(OrientationCheckTest, ConstantVendorOffsetIsMeasuredAcrossNorth) {
    io::SectionTable t = makeSyntheticWell(syntheticProfile("build", 300.0, 0.5));
    for (double& p : t.p1az_deg) p = std::fmod(p + 357.0, 360.0);  // -3 deg
    const OrientationOffset o = padAzimuthOffset(t);
    EXPECT_NEAR(o.mean_deg, -3.0, 1e-6);
}

TEST(OrientationCheckTest, NoSamplesWithoutAllFourCurves) {
    io::SectionTable t = makeSyntheticWell(syntheticProfile("build", 300.0, 0.5));
    t.rb_deg.clear();
    const OrientationOffset o = padAzimuthOffset(t);
    EXPECT_EQ(o.samples, 0u);
    EXPECT_TRUE(std::isnan(o.mean_deg));
}

#include "reconstruction/section/arm_geometry.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "support/reconstruction_support.h"

using namespace caliper3d::reconstruction;

TEST(ArmGeometryTest, SixArmsFollowTheReferenceTable) {
    const double expected[] = {0, 300, 240, 180, 120, 60};
    for (int k = 1; k <= 6; ++k)
        EXPECT_DOUBLE_EQ(armToolAngle_deg(k, 6), expected[k - 1]) << "arm " << k;
}

TEST(ArmGeometryTest, ArmOneLiesOnPlusXAndArmsGoClockwise) {
    const std::vector<double> radii{100, 100, 100, 100, 100, 100};
    const auto p = armPoints(radii.data(), 6);
    EXPECT_NEAR(p[0].x, 100.0, 1e-12);
    EXPECT_NEAR(p[0].y, 0.0, 1e-12);
    // Arm 2 is 60 degrees clockwise: negative Y in the tool frame.
    EXPECT_NEAR(p[1].x, 50.0, 1e-12);
    EXPECT_NEAR(p[1].y, -100.0 * std::sqrt(3.0) / 2.0, 1e-12);
    EXPECT_NEAR(p[3].x, -100.0, 1e-12);
}

TEST(ArmGeometryTest, PadAzimuthRotatesEveryArm) {
    EXPECT_DOUBLE_EQ(armAzimuth_deg(1, 6, 0.0), 0.0);
    EXPECT_DOUBLE_EQ(armAzimuth_deg(2, 6, 0.0), 60.0);
    EXPECT_DOUBLE_EQ(armAzimuth_deg(1, 6, 30.0), 30.0);
    EXPECT_DOUBLE_EQ(armAzimuth_deg(4, 6, 30.0), 210.0);
    EXPECT_DOUBLE_EQ(armAzimuth_deg(6, 6, 350.0), 290.0);
    EXPECT_DOUBLE_EQ(armAzimuth_deg(2, 6, 330.0), 30.0);  // wraps past north
    EXPECT_DOUBLE_EQ(armAzimuth_deg(3, 4, 10.0), 190.0);
}

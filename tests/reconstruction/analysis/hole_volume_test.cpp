#include "reconstruction/analysis/hole_volume.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "support/reconstruction_support.h"

using namespace caliper3d::reconstruction;

TEST(HoleVolumeTest, CylinderOfBitSizeAndItsAnnulusWithExcess) {
    const double bit = 311.15, casing = 244.48;  // 12 1/4 in hole, 9 5/8 in casing
    std::vector<double> md, area, bits;
    for (int i = 0; i <= 100; ++i) {
        md.push_back(i * 1.0);
        area.push_back(M_PI / 4 * bit * bit);
        bits.push_back(bit);
    }
    VolumeOptions o;
    o.casingOd_mm = casing;
    o.excess = 0.3;
    const HoleVolume v = holeVolume(md, area, bits, o);
    const double hole = M_PI / 4 * std::pow(bit / 1000, 2) * 100.0;
    const double annulus = hole - M_PI / 4 * std::pow(casing / 1000, 2) * 100.0;
    EXPECT_NEAR(v.hole_m3, hole, 1e-9);
    EXPECT_NEAR(v.gaugeHole_m3, hole, 1e-9);
    EXPECT_NEAR(v.annulus_m3, annulus, 1e-9);
    EXPECT_NEAR(v.cement_m3, annulus * 1.3, 1e-9);
    EXPECT_NEAR(v.gaugeCement_m3, annulus * 1.3, 1e-9);
}

TEST(HoleVolumeTest, IntervalIsClippedAndAreasInterpolatedInsideASection) {
    const std::vector<double> md{0, 10}, area{1e6, 3e6},
        bit{std::nan(""), std::nan("")};  // 1 and 3 m^2
    VolumeOptions o;
    o.top_m = 5.0;
    o.bottom_m = 20.0;
    const HoleVolume v = holeVolume(md, area, bit, o);
    EXPECT_DOUBLE_EQ(v.top_m, 5.0);
    EXPECT_DOUBLE_EQ(v.bottom_m, 10.0);
    EXPECT_NEAR(v.hole_m3, (2.0 + 3.0) / 2 * 5.0, 1e-12);
    EXPECT_DOUBLE_EQ(v.gaugeHole_m3, 0.0);
}

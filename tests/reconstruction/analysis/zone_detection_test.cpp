#include "reconstruction/analysis/zone_detection.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

using namespace caliper3d::reconstruction;

TEST(ZoneDetectionTest, DoubledAnglesAverageAcrossTheZeroOneEightySeam) {
    const AxialStatistics s = axialStatistics({170.0, 10.0});
    EXPECT_NEAR(std::min(s.mean_deg, 180.0 - s.mean_deg), 0.0, 1e-9);
    // R = cos(20 deg) for doubled angles +-20: SD = sqrt(-2 ln cos 20) / 2.
    EXPECT_NEAR(s.sd_deg,
                std::sqrt(-2.0 * std::log(std::cos(20.0 * M_PI / 180))) / 2.0 * 180 / M_PI, 1e-9);
    EXPECT_NEAR(axialStatistics({45.0, 45.0, 45.0}).sd_deg, 0.0, 1e-6);
    EXPECT_TRUE(std::isnan(axialStatistics({std::nan("")}).mean_deg));
}

TEST(ZoneDetectionTest, ZonesHaveTopBottomLengthAndMeanAzimuth) {
    using C = BoreholeClass;
    const std::vector<double> md{0, 1, 2, 3, 4, 5, 6};
    const std::vector<C> cls{C::InGauge, C::Breakout, C::Breakout, C::InGauge,
                             C::Washout, C::Washout,  C::Washout};
    const std::vector<double> az{0, 100, 110, 0, 0, 0, 0}, dmax{0, 240, 242, 0, 250, 250, 250},
        dmin(7, 216.0);
    const auto zones = detectZones(md, cls, az, dmax, dmin);
    ASSERT_EQ(zones.size(), 2u);
    EXPECT_EQ(zones[0].kind, C::Breakout);
    EXPECT_DOUBLE_EQ(zones[0].top_m, 0.5);
    EXPECT_DOUBLE_EQ(zones[0].bottom_m, 2.5);
    EXPECT_DOUBLE_EQ(zones[0].length_m, 2.0);
    EXPECT_NEAR(zones[0].meanAzimuth_deg, 105.0, 1e-9);
    EXPECT_DOUBLE_EQ(zones[0].meanDmax_mm, 241.0);
    EXPECT_EQ(zones[1].kind, C::Washout);
    EXPECT_DOUBLE_EQ(zones[1].bottom_m, 6.0);
}

TEST(ZoneDetectionTest, WsmQualityFollowsZoneCountLengthAndSpread) {
    auto zones = [](int count, double length, double spread) {
        std::vector<Zone> z(static_cast<std::size_t>(count));
        for (int i = 0; i < count; ++i) {
            z[static_cast<std::size_t>(i)].length_m = length;
            z[static_cast<std::size_t>(i)].meanAzimuth_deg = 60.0 + (i % 2 ? spread : -spread);
        }
        return z;
    };
    EXPECT_EQ(summariseBreakouts(zones(10, 31.0, 5.0)).quality, 'A');
    EXPECT_EQ(summariseBreakouts(zones(10, 29.0, 5.0)).quality, 'B');
    EXPECT_EQ(summariseBreakouts(zones(6, 17.0, 15.0)).quality, 'B');
    EXPECT_EQ(summariseBreakouts(zones(4, 8.0, 20.0)).quality, 'C');
    EXPECT_EQ(summariseBreakouts(zones(3, 50.0, 30.0)).quality, 'D');
    EXPECT_EQ(summariseBreakouts(zones(10, 50.0, 45.0)).quality, 'E');
    EXPECT_EQ(summariseBreakouts({}).quality, 'E');
    const BreakoutSummary s = summariseBreakouts(zones(4, 10.0, 0.0));
    EXPECT_NEAR(s.meanAzimuth_deg, 60.0, 1e-9);
    EXPECT_NEAR(s.shmaxAzimuth_deg, 150.0, 1e-9);
    EXPECT_DOUBLE_EQ(s.combinedLength_m, 40.0);
}

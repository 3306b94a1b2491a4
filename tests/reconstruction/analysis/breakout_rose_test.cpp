#include "reconstruction/analysis/breakout_rose.h"

#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

using namespace caliper3d::reconstruction;

namespace {

Zone zone(BoreholeClass kind, double length_m, double azimuth_deg) {
    Zone z;
    z.kind = kind;
    z.length_m = length_m;
    z.meanAzimuth_deg = azimuth_deg;
    return z;
}

}  // namespace

TEST(BreakoutRoseTest, WeighsEachBreakoutByItsLengthInTheBinOfItsAxis) {
    const std::vector<Zone> zones{
        zone(BoreholeClass::Breakout, 5.0, 135.0),   // bin 13, [130, 140)
        zone(BoreholeClass::Breakout, 2.5, 139.9),   // bin 13 too
        zone(BoreholeClass::Breakout, 4.0, 315.0),   // the same axis as 135: bin 13
        zone(BoreholeClass::Breakout, 1.0, 0.0),     // bin 0
        zone(BoreholeClass::Breakout, 3.0, 180.0),   // axis 0: bin 0
        zone(BoreholeClass::Breakout, 7.0, 179.99),  // bin 17
        zone(BoreholeClass::Washout, 50.0, 45.0),    // not a breakout: left out
        zone(BoreholeClass::Keyseat, 50.0, 95.0),
    };
    const BreakoutRose rose = breakoutRose(zones);
    ASSERT_EQ(rose.axial_m.size(), 18u);
    for (std::size_t i = 0; i < rose.axial_m.size(); ++i) {
        const double expected = i == 13 ? 11.5 : i == 0 ? 4.0 : i == 17 ? 7.0 : 0.0;
        EXPECT_DOUBLE_EQ(rose.axial_m[i], expected) << "bin " << i;
    }
    EXPECT_DOUBLE_EQ(rose.largest_m(), 11.5);
    // The bins hold the combined length of the breakouts, once.
    const BreakoutSummary summary = summariseBreakouts(zones);
    EXPECT_DOUBLE_EQ(std::accumulate(rose.axial_m.begin(), rose.axial_m.end(), 0.0),
                     summary.combinedLength_m);
}

TEST(BreakoutRoseTest, MirrorsEveryBinHalfATurnAway) {
    const BreakoutRose rose = breakoutRose(
        {zone(BoreholeClass::Breakout, 6.0, 62.0), zone(BoreholeClass::Breakout, 2.0, 248.0)});
    const std::vector<double> all = rose.mirrored();
    ASSERT_EQ(all.size(), 36u);
    // 62 -> [60, 70) and [240, 250); 248 is the axis 68: the same bins.
    EXPECT_DOUBLE_EQ(all[6], 8.0);
    EXPECT_DOUBLE_EQ(all[24], 8.0);
    for (std::size_t i = 0; i < 18; ++i) EXPECT_DOUBLE_EQ(all[i], all[i + 18]);
    EXPECT_DOUBLE_EQ(std::accumulate(all.begin(), all.end(), 0.0), 16.0);
}

TEST(BreakoutRoseTest, LeavesOutBreakoutsWithoutAnAzimuthAndTakesOtherBinWidths) {
    const BreakoutRose rose = breakoutRose({zone(BoreholeClass::Breakout, 3.0, std::nan("")),
                                            zone(BoreholeClass::Breakout, 1.0, 44.0)},
                                           15.0);
    ASSERT_EQ(rose.axial_m.size(), 12u);
    EXPECT_DOUBLE_EQ(rose.axial_m[2], 1.0);  // [30, 45)
    EXPECT_DOUBLE_EQ(std::accumulate(rose.axial_m.begin(), rose.axial_m.end(), 0.0), 1.0);
    EXPECT_DOUBLE_EQ(breakoutRose({}).largest_m(), 0.0);
    EXPECT_THROW(breakoutRose({}, 7.0), std::invalid_argument);
    EXPECT_THROW(breakoutRose({}, 0.0), std::invalid_argument);
}

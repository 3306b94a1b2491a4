#include "reconstruction/synthetic/synthetic_field.h"

#include <cmath>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

using namespace caliper3d::reconstruction;

// A field of seven: the first wellhead at the origin, the heads a regular heptagon with 25 m
// sides, every well drilled away from the heptagon's centre (its heads' mean), the profiles
// in turn.
TEST(SyntheticFieldTest, WellheadsLieOnARingAndEveryWellIsDrilledAwayFromItsCentre) {
    constexpr std::size_t kWells = 7;
    std::vector<SyntheticFieldWell> wells;
    double north = 0.0, east = 0.0;
    for (std::size_t w = 0; w < kWells; ++w) {
        wells.push_back(syntheticFieldWell(w, kWells, 100.0, 0.5));
        north += wells.back().north_m / double(kWells);
        east += wells.back().east_m / double(kWells);
    }
    EXPECT_DOUBLE_EQ(wells[0].north_m, 0.0);
    EXPECT_DOUBLE_EQ(wells[0].east_m, 0.0);
    const double radius = 25.0 / (2.0 * std::sin(3.14159265358979323846 / double(kWells)));
    const std::vector<std::string> profiles = syntheticProfileNames();
    for (std::size_t w = 0; w < kWells; ++w) {
        const SyntheticFieldWell& well = wells[w];
        const SyntheticFieldWell& next = wells[(w + 1) % kWells];
        EXPECT_NEAR(std::hypot(next.north_m - well.north_m, next.east_m - well.east_m), 25.0, 1e-9);
        const double dn = well.north_m - north, de = well.east_m - east;
        EXPECT_NEAR(std::hypot(dn, de), radius, 1e-9);
        double bearing = std::atan2(de, dn) * 180.0 / 3.14159265358979323846;
        if (bearing < 0.0) bearing += 360.0;
        EXPECT_NEAR(well.spec.holeAzimuth_deg, bearing, 1e-9) << "well " << w;
        EXPECT_EQ(well.profile, profiles[w]);
        EXPECT_DOUBLE_EQ(well.elevation_m, 25.0 + double(w % 3));
    }
    // The first well keeps its profile's own azimuth: the example builds towards 45 degrees.
    EXPECT_DOUBLE_EQ(wells[0].spec.holeAzimuth_deg,
                     syntheticProfile("example", 100.0, 0.5).holeAzimuth_deg);
}

// One well: at the origin, its profile as it is.
TEST(SyntheticFieldTest, AFieldOfOneIsItsFirstProfile) {
    const SyntheticFieldWell well = syntheticFieldWell(0, 1, 100.0, 0.5);
    EXPECT_EQ(well.profile, "example");
    EXPECT_DOUBLE_EQ(well.north_m, 0.0);
    EXPECT_DOUBLE_EQ(well.east_m, 0.0);
    EXPECT_DOUBLE_EQ(well.spec.holeAzimuth_deg, 45.0);
}

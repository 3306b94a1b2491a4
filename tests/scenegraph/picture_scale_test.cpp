#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/section/section_frame.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_geometry.h"
#include "scenegraph/picture_scale.h"

namespace caliper3d::scenegraph {
namespace {

TEST(PictureScaleTest, TickSpacingOfKnownLengths) {
    EXPECT_DOUBLE_EQ(tickSpacing_m(10.0), 1.0);
    EXPECT_DOUBLE_EQ(tickSpacing_m(15.0), 1.0);  // 15 ticks: the most allowed
    EXPECT_DOUBLE_EQ(tickSpacing_m(16.0), 2.0);
    EXPECT_DOUBLE_EQ(tickSpacing_m(31.0), 5.0);
    EXPECT_DOUBLE_EQ(tickSpacing_m(160.0), 20.0);
    EXPECT_DOUBLE_EQ(tickSpacing_m(188.0), 20.0);  // the STAR log's wellhead to bottom
    EXPECT_DOUBLE_EQ(tickSpacing_m(1000.0), 100.0);
    EXPECT_DOUBLE_EQ(tickSpacing_m(4000.0), 500.0);
    EXPECT_DOUBLE_EQ(tickSpacing_m(0.5), 0.05);
}

TEST(PictureScaleTest, EveryLengthGetsSixToFifteenTicksFromTheOneTwoFiveSeries) {
    for (double length = 0.3; length < 2.0e5; length *= 1.037) {
        const double spacing = tickSpacing_m(length);
        const double ticks = length / spacing;
        EXPECT_LE(ticks, 15.0 + 1e-9) << length;
        EXPECT_GT(ticks, 6.0) << length;
        const double mantissa = spacing / std::pow(10.0, std::floor(std::log10(spacing) + 1e-9));
        EXPECT_TRUE(std::abs(mantissa - 1.0) < 1e-9 || std::abs(mantissa - 2.0) < 1e-9 ||
                    std::abs(mantissa - 5.0) < 1e-9)
            << spacing;
    }
}

TEST(PictureScaleTest, RoundsUpToOneTwoThreeFive) {
    EXPECT_DOUBLE_EQ(roundUpToSeries(1.0), 1.0);
    EXPECT_DOUBLE_EQ(roundUpToSeries(1.2), 2.0);
    EXPECT_DOUBLE_EQ(roundUpToSeries(2.5), 3.0);
    EXPECT_DOUBLE_EQ(roundUpToSeries(4.0), 5.0);
    EXPECT_DOUBLE_EQ(roundUpToSeries(69.5), 100.0);
    EXPECT_DOUBLE_EQ(roundUpToSeries(278.0), 300.0);
    EXPECT_DOUBLE_EQ(roundUpToSeries(300.0), 300.0);
}

TEST(PictureScaleTest, RoundsDownToOneTwoThreeFive) {
    EXPECT_DOUBLE_EQ(roundDownToSeries(1.0), 1.0);
    EXPECT_DOUBLE_EQ(roundDownToSeries(1.9), 1.0);
    EXPECT_DOUBLE_EQ(roundDownToSeries(2.5), 2.0);
    EXPECT_DOUBLE_EQ(roundDownToSeries(4.9), 3.0);
    EXPECT_DOUBLE_EQ(roundDownToSeries(23.16), 20.0);
    EXPECT_DOUBLE_EQ(roundDownToSeries(100.0), 100.0);
    EXPECT_DOUBLE_EQ(roundDownToSeries(999.0), 500.0);
    EXPECT_DOUBLE_EQ(roundDownToSeries(0.7), 0.5);
}

// The factors a field's coarse meshes are planned for hold every factor the picture chooses.
TEST(PictureScaleTest, TheSeriesOfExaggerationsHoldsEveryFactorChosen) {
    const std::vector<double> series = seriesExaggerations();
    EXPECT_EQ(series, (std::vector<double>{1, 2, 3, 5, 10, 20, 30, 50, 100, 200, 300, 500, 1000}));
    for (double extent = 1.0; extent < 1.0e6; extent *= 1.37)
        for (const double radius : {0.05, 0.1, 0.2}) {
            const double chosen = autoExaggeration(extent, radius, 800);
            EXPECT_TRUE(std::find(series.begin(), series.end(), chosen) != series.end()) << chosen;
            const double separated = separatedExaggeration(extent / 100.0, radius, radius);
            if (separated >= 1.0) {
                EXPECT_TRUE(std::find(series.begin(), series.end(), separated) != series.end())
                    << separated;
            }
        }
}

TEST(PictureScaleTest, AutoExaggerationOfKnownWells) {
    const double r = 0.10795;  // 8.5 in bit
    // 1.5 % of 1000 m is 15 m of diameter: 69.5 times the 0.2159 m hole, stated as 100.
    EXPECT_DOUBLE_EQ(autoExaggeration(1000.0, r, 768), 100.0);
    EXPECT_DOUBLE_EQ(autoExaggeration(4000.0, r, 768), 300.0);
    EXPECT_DOUBLE_EQ(autoExaggeration(10.0, r, 768), 1.0);  // the hole reads as it is
    // A small picture needs 4 pixels: 4 % of a 100 px picture.
    EXPECT_DOUBLE_EQ(autoExaggeration(1000.0, r, 100), 200.0);
    EXPECT_DOUBLE_EQ(autoExaggeration(1.0e6, r, 768), kMaxExaggeration);
    EXPECT_DOUBLE_EQ(autoExaggeration(1000.0, std::nan(""), 768), 1.0);
}

TEST(PictureScaleTest, AutoExaggerationDrawsTheDiameterAtLeastTheFractionAsked) {
    for (double extent = 5.0; extent < 2.0e4; extent *= 1.09)
        for (double r : {0.05, 0.10795, 0.2}) {
            const double factor = autoExaggeration(extent, r, 768);
            const double drawn = 2.0 * r * factor / extent;
            if (factor > 1.0 && factor < kMaxExaggeration) {
                EXPECT_GE(drawn, kMinDrawnDiameter * (1.0 - 1e-12)) << extent << " " << r;
                EXPECT_LE(drawn, kMinDrawnDiameter * 2.0 + 1e-12) << extent << " " << r;
            }
        }
}

TEST(PictureScaleTest, TypicalRadiusAndExtentOfAGaugeWell) {
    auto table = std::make_shared<const io::SectionTable>(
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("circle", 1000, 0.5)));
    const reconstruction::WellGeometry g(table, reconstruction::GeometryOptions{});
    EXPECT_NEAR(typicalRadius_m(g, 0.0, 1000.0), 0.10795, 1e-9);
    Bounds whole, part;
    addPathBounds(g, 0.0, 1000.0, whole);
    addPathBounds(g, 400.0, 500.0, part);
    EXPECT_NEAR(whole.diagonal(), 1000.0, 1e-6);
    EXPECT_NEAR(part.diagonal(), 100.0, 1e-6);
    EXPECT_TRUE(Bounds().empty());
}

// A `profile` well 1000 m long (8.5 in bit), its wellhead `north_m`, `east_m` from the origin.
std::shared_ptr<const reconstruction::WellGeometry> wellAt(const std::string& profile,
                                                           double north_m, double east_m = 0.0) {
    auto table = std::make_shared<const io::SectionTable>(
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile(profile, 1000, 0.5)));
    reconstruction::GeometryOptions options;
    options.wellheadOffset = {north_m, east_m, 0.0};
    return std::make_shared<const reconstruction::WellGeometry>(table, options);
}

TEST(PictureScaleTest, SeparatedExaggerationKeepsHalfTheSpacingBetweenTheTubes) {
    const double r = 0.10795;
    // 10 m apart: 0.5 x 10 / 0.2159 = 23.2, stated as 20.
    EXPECT_DOUBLE_EQ(separatedExaggeration(10.0, r, r), 20.0);
    EXPECT_DOUBLE_EQ(separatedExaggeration(100.0, r, r), 200.0);
    EXPECT_DOUBLE_EQ(separatedExaggeration(1.0e6, r, r), kMaxExaggeration);
    // Closer than twice the two radii: no factor from 1 keeps them apart.
    EXPECT_DOUBLE_EQ(separatedExaggeration(0.4, r, r), 0.0);
    EXPECT_DOUBLE_EQ(separatedExaggeration(0.0, r, r), 0.0);
}

TEST(PictureScaleTest, ClosestApproachOfTwoVerticalWells) {
    const auto a = wellAt("circle", 0.0);
    EXPECT_NEAR(closestApproach_m(*a, *wellAt("circle", 10.0), 0.0, 1000.0), 10.0, 1e-6);
    EXPECT_NEAR(closestApproach_m(*a, *wellAt("circle", 6.0, 8.0), 0.0, 1000.0), 10.0, 1e-6);
    EXPECT_NEAR(closestApproach_m(*a, *a, 0.0, 1000.0), 0.0, 1e-9);
    EXPECT_NEAR(maxRadius_m(*a, 0.0, 1000.0), 0.10795, 1e-9);
}

// A well that kicks off at 200 m from 40 m north and 5 m east of the origin and builds south
// passes 5 m beside a vertical well at the origin, some 500 m down: the closest approach found
// over the sampled paths is, within the sampling, the least distance between two rows' centres.
TEST(PictureScaleTest, ClosestApproachOfAWellBuildingTowardsAnotherIsFoundDeepDown) {
    const auto a = wellAt("circle", 0.0);
    reconstruction::SyntheticWellSpec spec = reconstruction::syntheticProfile("circle", 1000, 0.5);
    spec.kickoff_m = 200.0;
    spec.buildRate_degPer30m = 1.5;
    spec.endOfBuild_m = 1000.0;
    spec.holeAzimuth_deg = 180.0;
    reconstruction::GeometryOptions options;
    options.wellheadOffset = {40.0, 5.0, 0.0};
    const reconstruction::WellGeometry b(
        std::make_shared<const io::SectionTable>(reconstruction::makeSyntheticWell(spec)), options);
    double least = std::numeric_limits<double>::infinity();
    std::size_t deepest = 0;
    for (std::size_t i = 0; i < a->table().rowCount(); ++i)
        for (std::size_t j = 0; j < b.table().rowCount(); ++j) {
            const double d = glm::length(a->centre(i) - b.centre(j));
            if (d < least) std::tie(least, deepest) = std::pair(d, j);
        }
    ASSERT_NEAR(least, 5.0, 0.1);                  // it passes beside the other well
    ASSERT_GT(b.table().depth_m[deepest], 400.0);  // deep down, not at the top
    const double found = closestApproach_m(*a, b, 0.0, 1000.0);
    EXPECT_NEAR(found, least, 0.05);  // rows 0.5 m apart, 1.5 m between the sampled points
    EXPECT_NEAR(closestApproach_m(b, *a, 0.0, 1000.0), found, 1e-9);
}

TEST(PictureScaleTest, TwoWellsTenMetresApartGetAFactorThatKeepsThemApart) {
    const auto a = wellAt("circle", 0.0);
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_DOUBLE_EQ(chooseExaggeration({a}, 0.0, inf, 768), 100.0);  // alone, as before
    EXPECT_DOUBLE_EQ(chooseExaggeration({a, wellAt("circle", 10.0)}, 0.0, inf, 768), 20.0);
    // 100 m apart they allow x 200: the picture's x 100 stands.
    EXPECT_DOUBLE_EQ(chooseExaggeration({a, wellAt("circle", 100.0)}, 0.0, inf, 768), 100.0);
    // The same hole twice: no factor keeps it apart from itself, and it is drawn as alone.
    EXPECT_DOUBLE_EQ(chooseExaggeration({a, wellAt("circle", 0.0)}, 0.0, inf, 768), 100.0);
    // Three wells: the nearest two decide.
    EXPECT_DOUBLE_EQ(
        chooseExaggeration({a, wellAt("circle", 100.0), wellAt("circle", 0.0, 5.0)}, 0.0, inf, 768),
        10.0);
}

// The farthest any drawn wall point lies from the path, over rows sampled every 10 m.
double drawnReach_m(const reconstruction::WellGeometry& g) {
    double reach = 0.0;
    for (std::size_t row = 0; row < g.table().rowCount(); row += 20) {
        const glm::dvec3 centre = reconstruction::toScene(g.centre(row));
        for (const glm::vec3& p : reconstruction::sectionRing(g, row))
            reach = std::max(reach, glm::length(glm::dvec3(p) - centre));
    }
    return reach;
}

TEST(PictureScaleTest, TubesAtTheChosenFactorDoNotOverlap) {
    const double inf = std::numeric_limits<double>::infinity();
    for (const char* profile : {"circle", "offcentre", "washout"}) {
        const auto a = wellAt(profile, 0.0), b = wellAt(profile, 10.0);
        const double factor = chooseExaggeration({a, b}, 0.0, inf, 768);
        const double alone = chooseExaggeration({a}, 0.0, inf, 768);
        ASSERT_LT(factor, alone) << profile;  // the limit is what decides here
        const double spacing = closestApproach_m(*a, *b, 0.0, 1000.0);
        const auto clearance = [&](double f) {
            return spacing - drawnReach_m(a->restyled(f, nullptr)) -
                   drawnReach_m(b->restyled(f, nullptr));
        };
        EXPECT_GT(clearance(factor), 0.0) << profile << " x" << factor;
        EXPECT_LT(clearance(alone), 0.0) << profile << " x" << alone;  // as drawn before
    }
}

}  // namespace
}  // namespace caliper3d::scenegraph

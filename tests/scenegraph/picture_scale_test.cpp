#include <cmath>
#include <memory>

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace caliper3d::scenegraph

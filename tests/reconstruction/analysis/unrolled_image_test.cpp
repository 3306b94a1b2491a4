// The unrolled wall against sections of known shape.
#include "reconstruction/analysis/unrolled_image.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include <glm/trigonometric.hpp>

#include "reconstruction/section/arm_geometry.h"
#include "reconstruction/synthetic/synthetic_well.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {

// The ellipse's radius at `azimuth_deg`, its major axis at `major_deg`: the synthetic
// wells' own ellipse (reconstruction/synthetic).
double ellipseRadius(double dmax, double dmin, double major_deg, double azimuth_deg) {
    return ellipseRadius_mm(dmax, dmin, azimuth_deg - major_deg);
}

// 101 sections 0.1 m apart from 100 m to 110 m, arm 1 at a P1AZ turning 3 degrees a row, each
// the ellipse dmax x dmin about the tool, major axis at `major_deg`; an 8.5 in bit.
io::SectionTable ellipseTable(int arms, double dmax, double dmin, double major_deg,
                              double inc_deg = 0.0, double azi_deg = 0.0) {
    io::SectionTable t;
    t.source = "ellipse";
    t.armCount = arms;
    for (int i = 0; i <= 100; ++i) {
        const double p1az = wrap360(3.0 * i);
        t.depth_m.push_back(100.0 + 0.1 * i);
        for (int k = 1; k <= arms; ++k)
            t.radius_mm.push_back(
                ellipseRadius(dmax, dmin, major_deg, p1az + armClockwiseAngle_deg(k, arms)));
        t.p1az_deg.push_back(p1az);
        t.devi_deg.push_back(inc_deg);
        t.hazi_deg.push_back(azi_deg);
        t.bitSize_mm.push_back(215.9);
    }
    return t;
}

WellGeometry geometryOf(io::SectionTable t) {
    return WellGeometry(std::make_shared<const io::SectionTable>(std::move(t)), GeometryOptions{});
}

UnrolledImageRequest window(double top_m, double bottom_m, int rows, int columns = 360) {
    UnrolledImageRequest r;
    r.top_m = top_m;
    r.bottom_m = bottom_m;
    r.rows = rows;
    r.columns = columns;
    return r;
}

}  // namespace

TEST(UnrolledImageTest, CircleFiveMillimetresOverGaugeDepartsFiveEverywhere) {
    const double radius = 215.9 / 2 + 5.0;
    const WellGeometry g = geometryOf(ellipseTable(8, 2 * radius, 2 * radius, 0.0));
    const UnrolledImage image = unrolledImage(g, window(100.0, 110.0, 50, 72));
    ASSERT_EQ(image.departure_mm.size(), 50u * 72u);
    for (float d : image.departure_mm) EXPECT_NEAR(d, 5.0, 1e-4);
}

TEST(UnrolledImageTest, EllipseDepartsMostAtItsMajorAxisAzimuthsHalfATurnApart) {
    // Major axis at azimuth 60; the tool turns, the image stays put.
    const WellGeometry g = geometryOf(ellipseTable(36, 245.9, 217.9, 60.0));
    const UnrolledImage image = unrolledImage(g, window(100.0, 110.0, 20));
    for (int r = 0; r < image.rows; ++r) {
        const float* row = image.departure_mm.data() + r * 360;
        const auto firstHalf = std::max_element(row, row + 180) - row;
        const auto secondHalf = std::max_element(row + 180, row + 360) - row;
        EXPECT_NEAR(image.columnAngle_deg(static_cast<int>(firstHalf)), 60.0, 1.0) << r;
        EXPECT_NEAR(image.columnAngle_deg(static_cast<int>(secondHalf)), 240.0, 1.0) << r;
        EXPECT_NEAR(row[firstHalf], 245.9 / 2 - 215.9 / 2, 0.05);
        const auto least = std::min_element(row, row + 180) - row;
        EXPECT_NEAR(image.columnAngle_deg(static_cast<int>(least)), 150.0, 1.0) << r;
        EXPECT_NEAR(row[least], 217.9 / 2 - 215.9 / 2, 0.05);
    }
}

TEST(UnrolledImageTest, HighSideReferenceTurnsTheImageByTheHighSidesAngle) {
    // Heading east at 30 degrees: the high side is 90 degrees clockwise from the plane's north.
    const WellGeometry g = geometryOf(ellipseTable(24, 245.9, 217.9, 60.0, 30.0, 90.0));
    const UnrolledImage north = unrolledImage(g, window(102.0, 104.0, 5));
    UnrolledImageRequest fromHighSide = window(102.0, 104.0, 5);
    fromHighSide.reference = AngleReference::HighSide;
    const UnrolledImage high = unrolledImage(g, fromHighSide);
    for (int r = 0; r < 5; ++r)
        for (int c = 0; c < 360; ++c) EXPECT_NEAR(high.at(r, c), north.at(r, (c + 90) % 360), 1e-4);
}

TEST(UnrolledImageTest, RowsWithoutDataBeyondTheLogOrWithoutGaugeAreNaN) {
    io::SectionTable t = ellipseTable(8, 230.0, 230.0, 0.0);
    for (std::size_t row = 40; row <= 60; ++row)  // 104 m to 106 m: one arm of eight left
        for (int k = 1; k < 8; ++k) t.radii(row)[k] = io::kNaN;
    const WellGeometry g = geometryOf(std::move(t));
    // 96.1 m to 114.1 m in 0.5 m rows: a row takes the nearest section within half its height.
    const UnrolledImage image = unrolledImage(g, window(96.1, 114.1, 36, 36));
    for (int r = 0; r < image.rows; ++r) {
        const double md = image.rowDepth_m(r);
        const bool data = md > 99.75 && md < 110.25 && (md < 103.95 || md > 106.05);
        for (int c = 0; c < image.columns; ++c) {
            if (data)
                EXPECT_NEAR(image.at(r, c), 115.0 - 107.95, 1e-4) << md;
            else
                EXPECT_TRUE(std::isnan(image.at(r, c))) << md;
        }
    }
    // No bit size: NaN everywhere, unless a gauge is given.
    io::SectionTable noBit = ellipseTable(8, 230.0, 230.0, 0.0);
    noBit.bitSize_mm.clear();
    const WellGeometry gauge = geometryOf(std::move(noBit));
    EXPECT_TRUE(std::isnan(unrolledImage(gauge, window(101.0, 102.0, 2, 4)).at(1, 2)));
    const UnrolledImage withGauge =
        unrolledImage(gauge, window(101.0, 102.0, 2, 4), [](std::size_t) { return 110.0; });
    EXPECT_NEAR(withGauge.at(1, 2), 5.0, 1e-4);
}

TEST(UnrolledImageTest, RowsWithoutTheReferenceAreNaNWhenTheHoleAzimuthIsUnknown) {
    // Inclined 5 degrees without a hole azimuth, arm 1 placed from P1AZ: north but no high side.
    io::SectionTable t = ellipseTable(8, 230.0, 230.0, 0.0, 5.0, 0.0);
    t.holeAzimuth = io::SectionTable::HoleAzimuth::Unknown;
    t.hazi_deg.clear();
    const WellGeometry g = geometryOf(std::move(t));
    UnrolledImageRequest request = window(101.0, 102.0, 2, 8);
    EXPECT_NEAR(unrolledImage(g, request).at(1, 3), 115.0 - 107.95, 1e-4);
    request.reference = AngleReference::HighSide;
    EXPECT_TRUE(std::isnan(unrolledImage(g, request).at(1, 3)));
}

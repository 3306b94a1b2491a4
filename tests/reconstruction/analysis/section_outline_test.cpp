// The polar outline of a section against sections of known shape.
#include "reconstruction/analysis/section_outline.h"

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include <glm/trigonometric.hpp>

#include "reconstruction/analysis/well_analysis.h"
#include "reconstruction/section/arm_geometry.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "test_support.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {

// The ellipse's radius at `azimuth_deg`, its major axis at `major_deg`: the synthetic
// wells' own ellipse (reconstruction/synthetic).
double ellipseRadius(double dmax, double dmin, double major_deg, double azimuth_deg) {
    return ellipseRadius_mm(dmax, dmin, azimuth_deg - major_deg);
}

// Ten sections 0.1 m apart from 100 m, arm 1 at P1AZ `p1az_deg`, each the ellipse dmax x dmin
// centred on the tool with its major axis at `major_deg` (dmax = dmin: a circle); an 8.5 in bit.
io::SectionTable ellipseTable(int arms, double dmax, double dmin, double major_deg, double p1az_deg,
                              double inc_deg = 0.0, double azi_deg = 0.0) {
    io::SectionTable t;
    t.source = "ellipse";
    t.armCount = arms;
    for (int i = 0; i < 10; ++i) {
        t.depth_m.push_back(100.0 + 0.1 * i);
        for (int k = 1; k <= arms; ++k)
            t.radius_mm.push_back(
                ellipseRadius(dmax, dmin, major_deg, p1az_deg + armClockwiseAngle_deg(k, arms)));
        t.p1az_deg.push_back(p1az_deg);
        t.devi_deg.push_back(inc_deg);
        t.hazi_deg.push_back(azi_deg);
        t.bitSize_mm.push_back(215.9);
    }
    return t;
}

WellGeometry geometryOf(io::SectionTable t) {
    return WellGeometry(std::make_shared<const io::SectionTable>(std::move(t)), GeometryOptions{});
}

double angleBetween(double a_deg, double b_deg, double period = 360.0) {
    const double d = std::fmod(std::abs(a_deg - b_deg), period);
    return std::min(d, period - d);
}

}  // namespace

TEST(SectionOutlineTest, CircularHoleHasAConstantSplineRadiusAndItsCircleAsEllipse) {
    const WellGeometry g = geometryOf(ellipseTable(8, 240.0, 240.0, 0.0, 37.0));
    const SectionOutline o = sectionOutline(g, 4, AngleReference::North, 96);
    ASSERT_TRUE(o.measured);
    ASSERT_EQ(o.pads.size(), 8u);
    ASSERT_EQ(o.spline.size(), 96u);
    for (const PolarPoint& p : o.spline) EXPECT_NEAR(p.radius_mm, 120.0, 1e-9);
    // Arm 1 points at its P1AZ, the others clockwise after it.
    EXPECT_NEAR(o.arm1Angle_deg, 37.0, 1e-9);
    for (int k = 0; k < 8; ++k) EXPECT_NEAR(o.pads[k].angle_deg, 37.0 + 45.0 * k, 1e-9);
    EXPECT_NEAR(o.ellipse.major_mm, 240.0, 1e-6);
    EXPECT_NEAR(o.ellipse.minor_mm, 240.0, 1e-6);
    EXPECT_NEAR(o.ellipse.centre.radius_mm, 0.0, 1e-6);
    EXPECT_NEAR(o.bitRadius_mm, 107.95, 1e-12);
    EXPECT_DOUBLE_EQ(o.northAngle_deg, 0.0);
    EXPECT_TRUE(std::isnan(o.highSideAngle_deg));  // vertical: no high side
}

TEST(SectionOutlineTest, EllipticalSectionGivesItsAxesAndAzimuthAsTheReportDoes) {
    // 36 arms on an ellipse 245.9 x 217.9 with its major axis at azimuth 60, the tool turned 17.
    const WellGeometry g = geometryOf(ellipseTable(36, 245.9, 217.9, 60.0, 17.0));
    const SectionOutline o = sectionOutline(g, 3, AngleReference::North);
    ASSERT_TRUE(o.ellipse.fitted);
    EXPECT_NEAR(o.ellipse.major_mm, 245.9, 0.05);
    EXPECT_NEAR(o.ellipse.minor_mm, 217.9, 0.05);
    EXPECT_NEAR(o.ellipse.majorAngle_deg, 60.0, 0.05);
    EXPECT_NEAR(o.ellipse.centre.radius_mm, 0.0, 0.01);
    // The report's figures for the same section.
    const WellAnalysis a = analyseWell(g, AnalysisOptions{});
    EXPECT_NEAR(o.ellipse.major_mm, a.sections[3].dmax_mm, test::storedInFloat(245.9));
    EXPECT_NEAR(o.ellipse.minor_mm, a.sections[3].dmin_mm, test::storedInFloat(217.9));
    EXPECT_NEAR(o.ellipse.majorAngle_deg, a.sections[3].majorAzimuth_deg,
                test::storedInFloat(60.0));
    // The ellipse's own points lie on it: the major end at 60 degrees, 122.95 mm out.
    const auto points = ellipsePoints(o.ellipse, 4);
    EXPECT_NEAR(points[0].angle_deg, 60.0, 0.05);
    EXPECT_NEAR(points[0].radius_mm, 245.9 / 2, 0.05);
    const auto minorAxis = ellipseAxis(o.ellipse, false, 3);
    EXPECT_NEAR(angleBetween(minorAxis[0].angle_deg, 150.0, 180.0), 0.0, 0.05);
    EXPECT_NEAR(minorAxis[0].radius_mm, 217.9 / 2, 0.05);
    EXPECT_NEAR(minorAxis[1].radius_mm, 0.0, 0.01);  // through the centre
}

TEST(SectionOutlineTest, PadsLieOnTheSplineRepairedOnesIncluded) {
    io::SectionTable t = ellipseTable(6, 250.0, 210.0, 20.0, 100.0);
    t.radii(5)[2] = io::kNaN;  // arm 3 missing: interpolated between its neighbours
    const WellGeometry g = geometryOf(std::move(t));
    const SectionOutline o = sectionOutline(g, 5, AngleReference::North, 48);
    ASSERT_EQ(o.pads.size(), 6u);
    for (std::size_t k = 0; k < 6; ++k) {
        const PolarPoint& onSpline = o.spline[8 * k];
        EXPECT_NEAR(onSpline.angle_deg, o.pads[k].angle_deg, 1e-9);
        EXPECT_NEAR(onSpline.radius_mm, o.pads[k].radius_mm, 1e-9);
    }
    EXPECT_NEAR(o.pads[2].radius_mm, (g.table().radii(5)[1] + g.table().radii(5)[3]) / 2, 1e-9);
}

TEST(SectionOutlineTest, InclinedHoleMarksTheHighSideAndCanBeSeenFromIt) {
    // Heading east at 30 degrees: the high side is 90 degrees clockwise from the plane's north.
    const WellGeometry g = geometryOf(ellipseTable(8, 240.0, 220.0, 0.0, 10.0, 30.0, 90.0));
    const SectionOutline north = sectionOutline(g, 2, AngleReference::North);
    EXPECT_NEAR(north.highSideAngle_deg, 90.0, 1e-9);
    EXPECT_NEAR(north.northAngle_deg, 0.0, 1e-9);
    const SectionOutline high = sectionOutline(g, 2, AngleReference::HighSide);
    EXPECT_NEAR(high.highSideAngle_deg, 0.0, 1e-9);
    EXPECT_NEAR(high.northAngle_deg, 270.0, 1e-9);
    // The same outline turned by 90 degrees.
    EXPECT_NEAR(angleBetween(high.arm1Angle_deg, north.arm1Angle_deg - 90.0), 0.0, 1e-9);
    EXPECT_NEAR(
        angleBetween(high.ellipse.majorAngle_deg, north.ellipse.majorAngle_deg - 90.0, 180.0), 0.0,
        1e-9);
    for (std::size_t j = 0; j < north.spline.size(); ++j)
        EXPECT_NEAR(high.spline[j].radius_mm, north.spline[j].radius_mm, 1e-12);
}

TEST(SectionOutlineTest, UnknownHoleAzimuthHasNoNorthAndNoDataHasNoShape) {
    // Inclined 20 degrees, no hole azimuth, arm 1 placed from RB: a high side but no north.
    io::SectionTable t = ellipseTable(8, 240.0, 240.0, 0.0, 10.0, 20.0, 0.0);
    t.holeAzimuth = io::SectionTable::HoleAzimuth::Unknown;
    t.p1az_deg.clear();
    t.hazi_deg.clear();
    t.rb_deg.assign(t.rowCount(), 30.0);
    for (int k = 0; k < 6; ++k) t.radii(7)[k] = io::kNaN;  // 2 of 8 arms: no data
    const WellGeometry g = geometryOf(std::move(t));
    const SectionOutline o = sectionOutline(g, 7, AngleReference::HighSide);
    EXPECT_TRUE(std::isnan(o.northAngle_deg));
    EXPECT_NEAR(o.highSideAngle_deg, 0.0, 1e-9);
    EXPECT_FALSE(o.measured);
    EXPECT_TRUE(o.pads.empty());
    EXPECT_TRUE(o.spline.empty());
    EXPECT_TRUE(sectionOutline(g, 6, AngleReference::HighSide).measured);
    EXPECT_NEAR(sectionOutline(g, 6, AngleReference::HighSide).arm1Angle_deg, 30.0, 1e-9);
}

TEST(SectionOutlineTest, UnknownHoleAzimuthWithPadAzimuthHasANorthButNoHighSide) {
    io::SectionTable t = ellipseTable(8, 240.0, 240.0, 0.0, 25.0, 5.0, 0.0);
    t.holeAzimuth = io::SectionTable::HoleAzimuth::Unknown;
    t.hazi_deg.clear();
    const WellGeometry g = geometryOf(std::move(t));
    const SectionOutline o = sectionOutline(g, 3, AngleReference::North);
    EXPECT_NEAR(o.northAngle_deg, 0.0, 1e-9);
    EXPECT_TRUE(std::isnan(o.highSideAngle_deg));
    // Arm 1's horizontal projection points at 25; in the plane tilted 5 degrees about east its
    // angle from the plane's north is atan(tan 25 cos 5) = 24.9164.
    const double inPlane =
        glm::degrees(std::atan(std::tan(glm::radians(25.0)) * std::cos(glm::radians(5.0))));
    EXPECT_NEAR(o.arm1Angle_deg, inPlane, 1e-9);
    EXPECT_NEAR(o.arm1Angle_deg, 24.9164, 1e-4);
}

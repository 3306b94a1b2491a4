#include "reconstruction/mesh/wall_point.h"

#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/section/section_analysis.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_geometry.h"

using namespace caliper3d::reconstruction;
using caliper3d::io::SectionTable;

namespace {

// A helix (30 degrees of inclination, the azimuth turning 3 degrees per 30 m) with the six
// arms of an off-centre tool: every section plane tilted and turned, every radius different.
std::shared_ptr<const SectionTable> helix() {
    SyntheticWellSpec spec = syntheticProfile("turn", 20.0, 0.05);
    spec.toolOffset_mm = 12.0;
    spec.toolOffsetAzimuth_deg = 70.0;
    return std::make_shared<const SectionTable>(makeSyntheticWell(spec));
}

double angleBetween(double a, double b) {
    double d = std::fmod(a - b, 360.0);
    if (d > 180.0) d -= 360.0;
    if (d <= -180.0) d += 360.0;
    return d;
}

}  // namespace

TEST(WallPointTest, EveryVertexOfLevelZeroIsTracedBackToItsSectionAndAngle) {
    for (double exaggeration : {1.0, 25.0}) {
        SCOPED_TRACE(exaggeration);
        GeometryOptions options;
        options.radialExaggeration = exaggeration;
        const WellGeometry g(helix(), options);
        const std::size_t segment = 7;
        const auto [first, last] = g.segmentRows(segment);
        const Mesh level0 = buildSegmentLevels(g, segment, 0, 1).levels.at(0);
        const int points = g.sampler().samples();
        ASSERT_EQ(level0.positions.size(), (last - first + 1) * static_cast<std::size_t>(points));
        std::vector<double> knots(static_cast<std::size_t>(g.knotCount()));
        std::vector<double> sampled(static_cast<std::size_t>(points));
        for (std::size_t row = first; row <= last; ++row) {
            g.sectionKnots(row, knots.data());
            g.sampler().sample(knots.data(), sampled.data());
            const PathPoint& p = g.path()[row];
            for (int j = 0; j < points; ++j) {
                // Ring `row - first`, vertex j: at 360 j / M clockwise from arm 1.
                const glm::vec3& v =
                    level0.positions[(row - first) * static_cast<std::size_t>(points) +
                                     static_cast<std::size_t>(j)];
                const WallPoint w = locateWallPoint(g, first, last, glm::dvec3(v));
                ASSERT_EQ(w.row, row) << j;
                const double phi = 360.0 * j / points;
                EXPECT_NEAR(angleBetween(w.fromArm1_deg, phi), 0.0, 1e-3) << row << " " << j;
                EXPECT_NEAR(
                    angleBetween(w.fromHighSide_deg,
                                 angleFromHighSide_deg(g.frame(row), p.inc_deg, p.azi_deg, phi)),
                    0.0, 1e-3);
                EXPECT_NEAR(angleBetween(w.azimuth_deg, inPlaneAzimuth_deg(g.frame(row), phi)), 0.0,
                            1e-3);
                // The true radius, not the drawn one: the spline sample the ring was drawn from.
                EXPECT_NEAR(w.radius_mm, sampled[static_cast<std::size_t>(j)], 1e-3);
                EXPECT_LT(std::abs(w.fromPlane_m), 1e-4);
            }
        }
    }
}

TEST(WallPointTest, APointBetweenTwoSectionsBelongsToTheNearerOne) {
    const WellGeometry g(helix(), GeometryOptions{});
    const auto [first, last] = g.segmentRows(3);
    const std::size_t row = first + 5;
    // On the way from row's wall point to the next row's, at a quarter and three quarters.
    const Ned a = g.centre(row) + 0.1 * g.frame(row).direction(1.0);
    const Ned b = g.centre(row + 1) + 0.1 * g.frame(row + 1).direction(1.0);
    const WallPoint nearA = locateWallPoint(g, first, last, toScene(a + 0.25 * (b - a)));
    const WallPoint nearB = locateWallPoint(g, first, last, toScene(a + 0.75 * (b - a)));
    EXPECT_EQ(nearA.row, row);
    EXPECT_EQ(nearB.row, row + 1);
    EXPECT_GT(nearA.fromPlane_m, 0.0);  // below row's plane
    EXPECT_LT(nearB.fromPlane_m, 0.0);  // above the next one's
    // Beyond the rows given: the end row of that side.
    EXPECT_EQ(locateWallPoint(g, first, last, toScene(g.centre(last + 3))).row, last);
    EXPECT_EQ(locateWallPoint(g, first, last, toScene(g.centre(first - 3))).row, first);
}

TEST(WallPointTest, UnknownHoleAzimuthLeavesTheAngleThatDependsOnItUndefined) {
    SectionTable t = *helix();
    t.hazi_deg.clear();
    t.holeAzimuth = SectionTable::HoleAzimuth::Unknown;
    const WellGeometry g(std::make_shared<const SectionTable>(t), GeometryOptions{});
    ASSERT_FALSE(g.holeAzimuthKnown());
    const std::size_t row = 200;
    ASSERT_GT(g.path()[row].inc_deg, 15.0);  // steep: arm 1 from RB
    ASSERT_EQ(g.orientation(row), WellGeometry::Orientation::RelativeBearing);
    const WallPoint w = locateWallPoint(g, row - 2, row + 2,
                                        toScene(g.centre(row) + 0.1 * g.frame(row).direction(0.5)));
    EXPECT_EQ(w.row, row);
    EXPECT_TRUE(std::isnan(w.azimuth_deg));  // as the report's azimuths from RB
    EXPECT_TRUE(std::isfinite(w.fromHighSide_deg));
    EXPECT_NEAR(angleBetween(w.fromArm1_deg, 180.0 * 0.5 / M_PI), 0.0, 1e-6);
}

// The path at any measured depth, and above the logged interval (docs/conventions.md, "Tie-in").
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "reconstruction/path/survey_interpolation.h"
#include "reconstruction/section/section_frame.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_geometry.h"
#include "reconstruction/well_path.h"

namespace caliper3d::reconstruction {
namespace {

// The log of `spec` from measured depth `top` down: a log whose first sample lies `top`
// metres below the depth reference.
std::shared_ptr<const io::SectionTable> logFrom(const SyntheticWellSpec& spec, double top) {
    const io::SectionTable whole = makeSyntheticWell(spec);
    std::size_t first = 0;
    while (whole.depth_m[first] < top - 1e-9) ++first;
    return std::make_shared<const io::SectionTable>(whole.rows(first, whole.rowCount()));
}

void expectNear(const Ned& a, const Ned& b, double tolerance, double md) {
    EXPECT_NEAR(a.x, b.x, tolerance) << "north at MD " << md;
    EXPECT_NEAR(a.y, b.y, tolerance) << "east at MD " << md;
    EXPECT_NEAR(a.z, b.z, tolerance) << "TVD at MD " << md;
}

TEST(WellPathTest, OnARowItIsThatRowsCentre) {
    const auto log = logFrom(syntheticProfile("build", 300.0, 0.5), 0.0);
    GeometryOptions options;
    options.wellheadOffset = {100.0, -50.0, 0.0};
    const WellGeometry g(log, options);
    for (std::size_t row : {0u, 1u, 60u, 333u, 600u}) {
        const PathSample at = pathAt(g, log->depth_m[row]);
        expectNear(at.position, g.centre(row), 1e-12, log->depth_m[row]);
        EXPECT_DOUBLE_EQ(at.inc_deg, g.path()[row].inc_deg);
    }
}

TEST(WellPathTest, BetweenRowsItLiesOnTheLineBetweenTheirCentres) {
    const auto log = logFrom(syntheticProfile("build", 300.0, 0.5), 0.0);
    const WellGeometry g(log, GeometryOptions{});
    const PathSample at = pathAt(g, 200.2);  // 40 % of the way from row 400 (200 m) to 401
    expectNear(at.position, g.centre(400) + (g.centre(401) - g.centre(400)) * 0.4, 1e-9, 200.2);
}

TEST(WellPathTest, AboveAVerticalLogItDropsStraightFromTheWellhead) {
    const auto log = logFrom(syntheticProfile("circle", 100.0, 0.5), 27.0);
    GeometryOptions options;
    options.wellheadOffset = {10.0, 20.0, 0.0};
    const WellGeometry g(log, options);
    for (double md : {0.0, 5.0, 13.5, 26.9}) {
        const PathSample at = pathAt(g, md);
        expectNear(at.position, Ned(10.0, 20.0, md), 1e-9, md);
        EXPECT_DOUBLE_EQ(at.inc_deg, 0.0);
    }
}

TEST(WellPathTest, AboveAnInclinedLogItFollowsTheTieInArc) {
    // First sample at MD 100, 10 deg towards east: the tie-in is one arc from a vertical
    // station at the wellhead, of radius 100 / (10 deg in radians) = 572.96 m. Half-way down
    // it (MD 50, 5 deg turned) TVD = R sin 5 deg and east = R (1 - cos 5 deg).
    auto table = std::make_shared<io::SectionTable>(
        makeSyntheticWell(syntheticProfile("circle", 10.0, 0.5)));
    for (std::size_t i = 0; i < table->rowCount(); ++i) {
        table->depth_m[i] += 100.0;
        table->devi_deg[i] = 10.0;
        table->hazi_deg[i] = 90.0;
    }
    const WellGeometry g(table, GeometryOptions{});
    const double radius = 100.0 / (10.0 * M_PI / 180.0);
    const PathSample half = pathAt(g, 50.0);
    EXPECT_NEAR(half.position.z, radius * std::sin(5.0 * M_PI / 180.0), 1e-6);
    EXPECT_NEAR(half.position.y, radius * (1.0 - std::cos(5.0 * M_PI / 180.0)), 1e-6);
    EXPECT_NEAR(half.position.x, 0.0, 1e-9);
    EXPECT_NEAR(half.inc_deg, 5.0, 1e-9);
    // At the first row the arc ends where the geometry placed that row.
    expectNear(pathAt(g, 100.0).position, g.centre(0), 1e-9, 100.0);
    expectNear(pathAt(g, 99.9999).position, g.centre(0), 1e-3, 99.9999);
}

TEST(WellPathTest, AboveTheLogWithASurveyItFollowsTheSurvey) {
    // A survey that builds from 10 m; the log starts at 60 m. Above the log the path is the
    // survey's, as the geometry's own rows are.
    const auto log = logFrom(syntheticProfile("circle", 100.0, 0.5), 60.0);
    GeometryOptions options;
    options.survey = {{10.0, 0.0, 30.0}, {40.0, 6.0, 30.0}, {100.0, 12.0, 30.0}};
    const WellGeometry g(log, options);
    const std::vector<PathPoint> expected =
        interpolateSurveyPath(tiedToSurface(options.survey), {20.0, 40.0, 55.0});
    for (const PathPoint& p : expected)
        expectNear(pathAt(g, p.md).position, Ned(p.north, p.east, p.tvd), 1e-9, p.md);
}

TEST(WellPathTest, UnloggedLineRunsFromTheWellheadToTheFirstRow) {
    const auto log = logFrom(syntheticProfile("circle", 100.0, 0.5), 27.0);
    GeometryOptions options;
    options.wellheadOffset = {10.0, 20.0, 0.0};
    const WellGeometry g(log, options);
    const std::vector<glm::vec3> line = unloggedPathLine(g, 1.0);
    ASSERT_EQ(line.size(), 28u);  // MD 0, 1, ... 26, then the first row at 27
    const glm::vec3 head(toScene(Ned(10.0, 20.0, 0.0)));
    const glm::vec3 first(toScene(g.centre(0)));
    for (int i = 0; i < 3; ++i) {
        EXPECT_FLOAT_EQ(line.front()[i], head[i]);
        EXPECT_FLOAT_EQ(line.back()[i], first[i]);
    }
    EXPECT_FLOAT_EQ(line[13].y, -13.0f);  // scene y is up: 13 m down
}

TEST(WellPathTest, NoUnloggedLineForALogFromTheWellheadOrAStretch) {
    const auto log = logFrom(syntheticProfile("circle", 100.0, 0.5), 0.0);
    EXPECT_TRUE(unloggedPathLine(WellGeometry(log, GeometryOptions{}), 1.0).empty());
    const auto deeper = logFrom(syntheticProfile("circle", 100.0, 0.5), 40.0);
    GeometryOptions stretch;
    stretch.continueFrom = PathPoint{};
    stretch.continueFrom->md = 40.0;
    stretch.continueFrom->tvd = 40.0;
    EXPECT_TRUE(unloggedPathLine(WellGeometry(deeper, stretch), 1.0).empty());
}

}  // namespace
}  // namespace caliper3d::reconstruction

// The tie-in of a log that does not start at the depth reference
// (docs/conventions.md, "Tie-in"): measured depth counts from the wellhead.
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "reconstruction/path/survey_interpolation.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {
namespace {

// The rows of `table` from measured depth `top` down, as a log whose first
// sample lies `top` metres below the depth reference.
std::shared_ptr<const io::SectionTable> rowsFrom(const io::SectionTable& table, double top) {
    auto out = std::make_shared<io::SectionTable>();
    out->source = table.source;
    out->armCount = table.armCount;
    const std::size_t n = static_cast<std::size_t>(table.armCount);
    for (std::size_t i = 0; i < table.rowCount(); ++i) {
        if (table.depth_m[i] < top - 1e-9) continue;
        out->depth_m.push_back(table.depth_m[i]);
        out->radius_mm.insert(out->radius_mm.end(), table.radii(i), table.radii(i) + n);
        out->p1az_deg.push_back(table.p1az_deg[i]);
        out->devi_deg.push_back(table.devi_deg[i]);
        out->hazi_deg.push_back(table.hazi_deg[i]);
        out->rb_deg.push_back(table.rb_deg[i]);
        out->bitSize_mm.push_back(table.bitSize_mm[i]);
    }
    return out;
}

// The spec's exact stations every `step` metres over [from, to].
std::vector<SurveyStation> stations(const SyntheticWellSpec& spec, double from, double to,
                                    double step) {
    std::vector<SurveyStation> out;
    for (double md = from; md <= to + 1e-9; md += step)
        out.push_back({md, syntheticInclination_deg(spec, md), syntheticAzimuth_deg(spec, md)});
    return out;
}

TEST(TieInTest, VerticalLogStartingAt27MetresHasTvdEqualToMd) {
    const auto log = rowsFrom(makeSyntheticWell(syntheticProfile("circle", 100.0, 0.5)), 27.0);
    ASSERT_DOUBLE_EQ(log->depth_m.front(), 27.0);
    const WellGeometry g(log, GeometryOptions{});
    for (std::size_t i = 0; i < log->rowCount(); ++i) {
        EXPECT_NEAR(g.path()[i].tvd, log->depth_m[i], 1e-9) << "row " << i;
        EXPECT_NEAR(g.path()[i].north, 0.0, 1e-12);
        EXPECT_NEAR(g.path()[i].east, 0.0, 1e-12);
    }
}

TEST(TieInTest, WithAndWithoutSurveyGiveTheSamePathForAVerticalTopHole) {
    // Vertical to 30 m, then 3 deg/30 m towards azimuth 30: one exact arc, which
    // minimum curvature reproduces from the log's 0.5 m rows and from a survey's
    // 10 m stations alike. The log starts at 27 m, below the depth reference.
    const SyntheticWellSpec spec = syntheticProfile("build", 300.0, 0.5);
    ASSERT_DOUBLE_EQ(spec.kickoff_m, 30.0);
    const auto log = rowsFrom(makeSyntheticWell(spec), 27.0);
    const WellGeometry fromLog(log, GeometryOptions{});
    GeometryOptions fromZero, fromTop;
    fromZero.survey = stations(spec, 0.0, 300.0, 10.0);  // the survey starts at the wellhead
    fromTop.survey = stations(spec, 30.0, 300.0, 10.0);  // it starts below the wellhead, tied in
    const WellGeometry surveyFromZero(log, fromZero), surveyFromTop(log, fromTop);
    for (std::size_t i = 0; i < log->rowCount(); ++i) {
        const PathPoint& p = fromLog.path()[i];
        for (const WellGeometry* g : {&surveyFromZero, &surveyFromTop}) {
            const PathPoint& q = g->path()[i];
            EXPECT_NEAR(p.tvd, q.tvd, 1e-6) << "MD " << p.md;
            EXPECT_NEAR(p.north, q.north, 1e-6) << "MD " << p.md;
            EXPECT_NEAR(p.east, q.east, 1e-6) << "MD " << p.md;
        }
        if (p.md <= 30.0) {
            EXPECT_NEAR(p.tvd, p.md, 1e-9);
        }
    }
    // Below the kickoff, the build arc of radius 572.96 m: at MD 130 (100 m of
    // arc) TVD 30 + 99.493 m and 8.704 m of departure towards azimuth 30.
    const std::size_t row = static_cast<std::size_t>((130.0 - 27.0) / 0.5);
    ASSERT_DOUBLE_EQ(log->depth_m[row], 130.0);
    const double radius = 30.0 / (3.0 * M_PI / 180.0);
    const double beta = 100.0 / radius;
    EXPECT_NEAR(fromLog.path()[row].tvd, 30.0 + radius * std::sin(beta), 1e-6);
    EXPECT_NEAR(std::hypot(fromLog.path()[row].north, fromLog.path()[row].east),
                radius * (1.0 - std::cos(beta)), 1e-6);
}

TEST(TieInTest, InclinedFirstSampleIsReachedByOneMinimumCurvatureArcFromVertical) {
    // First sample at MD 100 m, 10 deg towards east: the arc from a vertical
    // station at the wellhead has radius 100 / (10 deg in radians) = 572.96 m,
    // so TVD = R sin 10 = 99.4931 m and east = R (1 - cos 10) = 8.7046 m.
    auto log = std::make_shared<io::SectionTable>(
        makeSyntheticWell(syntheticProfile("circle", 10.0, 0.5)));
    for (std::size_t i = 0; i < log->rowCount(); ++i) {
        log->depth_m[i] += 100.0;
        log->devi_deg[i] = 10.0;
        log->hazi_deg[i] = 90.0;
    }
    const WellGeometry g(log, GeometryOptions{});
    EXPECT_NEAR(g.path()[0].tvd, 99.4931, 1e-4);
    EXPECT_NEAR(g.path()[0].east, 8.7046, 1e-4);
    EXPECT_NEAR(g.path()[0].north, 0.0, 1e-9);
}

TEST(TieInTest, SurveyBelowTheWellheadGetsAVerticalStationAtMdZero) {
    const std::vector<SurveyStation> tied = tiedToSurface({{50.0, 5.0, 200.0}, {80.0, 6.0, 201.0}});
    ASSERT_EQ(tied.size(), 3u);
    EXPECT_DOUBLE_EQ(tied[0].md, 0.0);
    EXPECT_DOUBLE_EQ(tied[0].inc_deg, 0.0);
    EXPECT_DOUBLE_EQ(tied[0].azi_deg, 200.0);
    // A survey that starts at the wellhead is left as it is.
    EXPECT_EQ(tiedToSurface({{0.0, 1.0, 10.0}, {30.0, 2.0, 10.0}}).size(), 2u);
}

}  // namespace
}  // namespace caliper3d::reconstruction

// Colouring one run's wall by its change against another run of the same well: a synthetic
// pair with known differences (a deeper counter, a tool turned 90 degrees, a washout 10 mm
// wider in the drawn run).
#include "reconstruction/analysis/run_change.h"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <utility>

#include <gtest/gtest.h>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

#include "reconstruction/analysis/section_angle_reference.h"
#include "reconstruction/mesh/colour_map.h"
#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_interval.h"
#include "support/run_pair.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {

using Kind = SyntheticFeature::Kind;

// The equivalent diameter of a 48-gon inscribed in a circle of diameter d is d times this.
const double kInscribed = std::sqrt(24.0 * std::sin(2.0 * M_PI / 48.0) / M_PI);

struct Run {
    std::shared_ptr<const WellGeometry> geometry;
    WellAnalysis analysis;
    ComparedRun compared() const { return {geometry.get(), &analysis}; }
};

Run analyse(const SyntheticWellSpec& spec) {
    Run r;
    auto table = std::make_shared<const io::SectionTable>(makeSyntheticWell(spec));
    r.geometry = std::make_shared<const WellGeometry>(table, GeometryOptions{});
    r.analysis = analyseWell(*r.geometry, AnalysisOptions{});
    return r;
}

// The other run: 150 m of vertical hole with a washout at 100-102 m. The drawn run: its
// counter 0.35 m deeper, its tool 90 degrees round, the washout 10 mm wider.
SyntheticWellSpec otherRun() {
    return widenedWashoutRuns(150.0, 100.0).first;
}
SyntheticWellSpec drawnRun() {
    return widenedWashoutRuns(150.0, 100.0).second;
}

struct Pair {
    Run drawn = analyse(drawnRun());
    Run other = analyse(otherRun());
    RunChange change = measureRunChange(drawn.compared(), other.compared(), "run2.las", "run1.las");
};

std::size_t rowAt(const WellGeometry& g, double md) {
    return static_cast<std::size_t>(std::lround((md - g.table().depth_m.front()) / 0.05));
}

const Pair& pair() {
    static const Pair kPair;
    return kPair;
}

}  // namespace

TEST(RunChangeTest, TheWidenedWashoutReadsItsChangeAndTheRestNone) {
    const Pair& p = pair();
    EXPECT_NEAR(p.change.mapping.shift_m, -0.35, 0.01);  // the other run reads 0.35 m shallower
    const WellGeometry& g = *p.drawn.geometry;
    const std::vector<float> change = changeAtDepths(p.change, g.table().depth_m);
    ASSERT_EQ(change.size(), g.table().rowCount());
    std::size_t inWashout = 0, unchanged = 0;
    for (std::size_t row = 0; row < change.size(); ++row) {
        const double md = g.table().depth_m[row];
        if (md > 100.45 && md < 102.25) {  // the washout, in the drawn run's depths
            EXPECT_NEAR(change[row], kInscribed * 10.0, 0.5) << md;
            ++inWashout;
        } else if (md > 0.4 && (md < 100.2 || md > 102.5)) {
            EXPECT_NEAR(change[row], 0.0, 0.5) << md;
            ++unchanged;
        }
    }
    EXPECT_GT(inWashout, 30u);
    EXPECT_GT(unchanged, 2900u);  // of 3001 rows
}

TEST(RunChangeTest, AboveTheOverlapThereIsNoChangeAndTheWallTakesTheNoValueColour) {
    const Pair& p = pair();
    const WellGeometry& g = *p.drawn.geometry;
    const auto colouring = changeColouring(g, p.change);
    // Both runs wrote 0-150 m; the drawn run's 0-0.30 m lie above the other's first depth
    // (0.35 m shallower), so they are beyond the overlap.
    std::size_t beyond = 0;
    for (std::size_t row = 0; row < g.table().rowCount(); ++row) {
        const double md = g.table().depth_m[row];
        if (md > 0.32 && md < 0.38) continue;  // the overlap's edge, within the match's 1 cm
        const float value = changeAtDepths(p.change, {md}).front();
        if (md < 0.35) {
            EXPECT_TRUE(std::isnan(value)) << md;
            EXPECT_EQ(colouring->colour(row, 110.0), kNoValueColour) << md;
            ++beyond;
        } else {
            EXPECT_FALSE(std::isnan(value)) << md;
            EXPECT_NE(colouring->colour(row, 110.0), kNoValueColour) << md;
        }
    }
    EXPECT_EQ(beyond, 7u);
    EXPECT_TRUE(colouring->legend().noValue);
}

TEST(RunChangeTest, TheWallIsColouredOnTheDivergingMapSymmetricAboutNoChange) {
    const Pair& p = pair();
    const WellGeometry& g = *p.drawn.geometry;
    const auto colouring = changeColouring(g, p.change);
    const ColourLegend& legend = colouring->legend();
    EXPECT_EQ(legend.kind, ColourMapKind::Diverging);
    EXPECT_DOUBLE_EQ(legend.lo, -legend.hi);
    // 40 of 3001 rows moved their wall by ~5 mm: the 98th percentile of |movement| is under
    // half the repeatability limit (24 arms: 3 mm), which the range keeps.
    EXPECT_DOUBLE_EQ(legend.hi, 1.5);
    EXPECT_EQ(legend.title, "run2.las minus run1.las");
    EXPECT_EQ(legend.unit, "mm");
    EXPECT_EQ(legend.centre, "no change");
    const std::size_t washout = rowAt(g, 101.3);
    const std::size_t gauge = rowAt(g, 50.0);
    // The widened washout at the red end (beyond the range: clamped), the gauge hole grey.
    EXPECT_EQ(colouring->colour(washout, 137.95), divergingColour(1.0));
    // Without a direction a point takes its section's mean movement, half the change of its
    // equivalent diameter.
    const float atGauge = changeAtDepths(p.change, {g.table().depth_m[gauge]}).front() / 2.0f;
    EXPECT_EQ(colouring->colour(gauge, 107.95),
              divergingColour(mapPosition(ColourMapKind::Diverging, atGauge, -1.5, 1.5)));
    EXPECT_NEAR(mapPosition(ColourMapKind::Diverging, atGauge, -1.5, 1.5), 0.5, 0.05);
    for (double angle = 0.0; angle < 360.0; angle += 15.0) {
        EXPECT_EQ(colouring->colour(washout, 137.95, angle), divergingColour(1.0)) << angle;
        const std::uint32_t c = colouring->colour(gauge, 107.95, angle);
        EXPECT_NEAR(red(c), red(divergingColour(0.5)), 12) << angle;
        EXPECT_NEAR(blue(c), blue(divergingColour(0.5)), 12) << angle;
    }
    // A range given is kept, and must hold no change.
    const auto given = changeColouring(g, p.change, std::make_pair(-20.0, 20.0));
    EXPECT_EQ(given->legend().range, "given");
    EXPECT_EQ(
        given->colour(washout, 0.0),
        divergingColour(mapPosition(
            ColourMapKind::Diverging,
            changeAtDepths(p.change, {g.table().depth_m[washout]}).front() / 2.0, -20.0, 20.0)));
    EXPECT_THROW(changeColouring(g, p.change, std::make_pair(2.0, 20.0)), std::invalid_argument);
}

TEST(RunChangeTest, AnIntervalOfTheDrawnRunTakesTheChangesOfItsDepths) {
    const Pair& p = pair();
    const WellGeometry& g = *p.drawn.geometry;
    const auto interval = intervalGeometry(g, 99.0, 104.0, g.options());
    const std::vector<float> whole = changeAtDepths(p.change, g.table().depth_m);
    const std::vector<float> part = changeAtDepths(p.change, interval->table().depth_m);
    ASSERT_EQ(part.size(), interval->table().rowCount());
    for (std::size_t row = 0; row < part.size(); ++row) {
        const std::size_t same =
            static_cast<std::size_t>(std::lround(interval->table().depth_m[row] / 0.05));
        EXPECT_EQ(part[row], whole[same]) << interval->table().depth_m[row];
    }
}

TEST(RunChangeTest, ChangesOfSeveralWellsShareOneSymmetricRange) {
    const Pair& p = pair();
    // The other run against itself: no change anywhere (the match finds a shift of about 0).
    const RunChange none =
        measureRunChange(p.other.compared(), p.other.compared(), "run1.las", "run1.las");
    ASSERT_GT(none.compared, 2900u);
    for (const float v : none.change_mm)
        if (std::isfinite(v)) {
            EXPECT_NEAR(v, 0.0, 0.01);  // the match is found to a sub-step shift, ~0
        }
    const RunChange widened = runChangeOf(compareRuns(p.drawn.compared(), p.other.compared(),
                                                      [&] {
                                                          RunComparisonOptions o;
                                                          o.mapping = p.change.mapping;
                                                          o.repeatability95_mm = 3.0;
                                                          return o;
                                                      }()),
                                          "run2.las", "run1.las");
    const auto shared =
        changeColourings({p.other.geometry, p.drawn.geometry}, {&none, &widened}, std::nullopt);
    ASSERT_EQ(shared.size(), 2u);
    EXPECT_DOUBLE_EQ(shared[0]->legend().hi, shared[1]->legend().hi);
    EXPECT_DOUBLE_EQ(shared[0]->legend().lo, -shared[0]->legend().hi);
    EXPECT_NE(shared[0]->legend().range.find("over all 2 wells"), std::string::npos);
}

TEST(RunChangeTest, ABreakoutThatGrewIsColouredAtItsAzimuthAndGreyAcrossIt) {
    // Run 1: a breakout 245.9 x 217.9 mm at 135 degrees over 40-45 m; run 2 (drawn), its
    // counter 0.35 m deeper and its tool 90 degrees round, the breakout 10 mm longer: the wall
    // moved 5 mm out at 135 and 315 degrees, not at all at 45 and 225.
    SyntheticWellSpec first = otherRun();
    first.features = {{Kind::Breakout, 40.0, 45.0, 245.9, 217.9, 135.0, 0.0}};
    SyntheticWellSpec second = drawnRun();
    second.features = first.features;
    second.features[0].dmax_mm += 10.0;
    const ::Run other = analyse(first), drawn = analyse(second);
    const RunChange change =
        measureRunChange(drawn.compared(), other.compared(), "run2.las", "run1.las");
    const auto colouring = changeColouring(*drawn.geometry, change);
    ASSERT_TRUE(colouring->byDirection());
    EXPECT_EQ(colouring->legend().note, "wall movement at each azimuth, shift -0.350 m");
    const WellGeometry& g = *drawn.geometry;
    std::size_t checked = 0;
    for (double md = 41.0; md < 44.5; md += 0.25) {
        const std::size_t row = rowAt(g, md);
        // A point's angle from arm 1 for an azimuth (a vertical hole: the section's north).
        const double arm1 = arm1Angle_deg(g.frame(row), AngleReference::North);
        ASSERT_TRUE(std::isfinite(arm1));
        for (const double tip : {135.0, 315.0}) {
            const std::uint32_t c = colouring->colour(row, 130.0, tip - arm1);
            EXPECT_EQ(c, divergingColour(1.0)) << md << " at " << tip;  // 5 mm: beyond 1.5
        }
        for (const double flank : {45.0, 225.0}) {
            const std::uint32_t c = colouring->colour(row, 110.0, flank - arm1);
            EXPECT_NEAR(red(c), red(divergingColour(0.5)), 25) << md << " at " << flank;
            EXPECT_NEAR(blue(c), blue(divergingColour(0.5)), 25) << md << " at " << flank;
        }
        ++checked;
    }
    EXPECT_EQ(checked, 14u);

    // The wall as drawn: each point of a ring coloured by its own azimuth from the ring's
    // centre (the scene's x east, z south).
    const WellGeometry coloured = g.restyled(1.0, colouring);
    std::vector<std::size_t> rows;
    for (double md = 41.0; md < 44.5; md += 0.5) rows.push_back(rowAt(g, md));
    constexpr int kPoints = 48;  // the full spline: every ring alike
    const Mesh mesh = buildRingMesh(coloured, rows, kPoints);
    ASSERT_EQ(mesh.positions.size(), rows.size() * kPoints);
    std::size_t tips = 0, flanks = 0;
    for (std::size_t ring = 0; ring < rows.size(); ++ring) {
        glm::dvec3 centre(0.0);
        for (int j = 0; j < kPoints; ++j) centre += glm::dvec3(mesh.positions[ring * kPoints + j]);
        centre /= static_cast<double>(kPoints);
        for (int j = 0; j < kPoints; ++j) {
            const glm::dvec3 d = glm::dvec3(mesh.positions[ring * kPoints + j]) - centre;
            const double azimuth = std::fmod(glm::degrees(std::atan2(d.x, -d.z)) + 360.0, 360.0);
            const auto near = [&](double a) {
                return std::abs(std::remainder(azimuth - a, 360.0)) < 12.0;
            };
            const std::uint32_t c = mesh.colours[ring * kPoints + j];
            if (near(135.0) || near(315.0)) {
                EXPECT_EQ(c, divergingColour(1.0)) << azimuth;
                ++tips;
            } else if (near(45.0) || near(225.0)) {
                EXPECT_NEAR(red(c), red(divergingColour(0.5)), 25) << azimuth;
                ++flanks;
            }
        }
    }
    EXPECT_GT(tips, 30u);
    EXPECT_GT(flanks, 30u);
}

#include "reconstruction/mesh/lod_levels.h"

#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_geometry.h"

using namespace caliper3d::reconstruction;
using caliper3d::io::SectionTable;

namespace {

constexpr double kBreakoutTop_m = 5.2, kBreakoutBottom_m = 6.2;  // a 1 m breakout

// A gauge hole (6 arms, 8.5 in bit) logged every 2.5 mm, with arms 1 and 4 reading 25 mm
// more over [kBreakoutTop_m, kBreakoutBottom_m): a breakout 1 m long.
std::shared_ptr<const SectionTable> breakoutWell() {
    SectionTable t = makeSyntheticWell(syntheticProfile("circle", 10.0, 0.0025));
    for (std::size_t r = 0; r < t.rowCount(); ++r)
        if (t.depth_m[r] >= kBreakoutTop_m && t.depth_m[r] < kBreakoutBottom_m) {
            t.radii(r)[0] += 25.0;
            t.radii(r)[3] += 25.0;
        }
    return std::make_shared<const SectionTable>(std::move(t));
}

std::vector<double> knots(const WellGeometry& g, std::size_t row) {
    std::vector<double> k(static_cast<std::size_t>(g.knotCount()));
    g.sectionKnots(row, k.data());
    return k;
}

}  // namespace

TEST(LodLevelsTest, EveryRowLeftOutIsInterpolatedWithinTheLevelsTolerance) {
    GeometryOptions options;
    options.segmentLength_m = 10.0;
    const WellGeometry g(breakoutWell(), options);
    const auto [first, last] = g.segmentRows(0);
    const std::vector<double>& depth = g.table().depth_m;
    for (const LodLevel& level : lodPyramid(options)) {
        const std::vector<std::size_t> rows = decimatedRows(g, first, last, level);
        ASSERT_EQ(rows.front(), first);
        ASSERT_EQ(rows.back(), last);
        for (std::size_t i = 1; i < rows.size(); ++i) {
            const std::size_t a = rows[i - 1], b = rows[i];
            ASSERT_LT(a, b);
            if (level.maxSpacing_m > 0.0 && b > a + 1)
                EXPECT_LE(depth[b] - depth[a], level.maxSpacing_m + 1e-9);
            const std::vector<double> ka = knots(g, a), kb = knots(g, b);
            for (std::size_t r = a + 1; r < b; ++r) {
                const double f = (depth[r] - depth[a]) / (depth[b] - depth[a]);
                const std::vector<double> k = knots(g, r);
                for (std::size_t j = 0; j < k.size(); ++j)
                    ASSERT_LE(std::abs(ka[j] + f * (kb[j] - ka[j]) - k[j]),
                              level.tolerance_mm + 1e-9)
                        << "row " << r << " arm " << j << " tolerance " << level.tolerance_mm;
            }
        }
    }
}

TEST(LodLevelsTest, CoarsestLevelKeepsAOneMetreBreakoutAndDropsTheGaugeHole) {
    GeometryOptions options;
    options.segmentLength_m = 10.0;
    const WellGeometry g(breakoutWell(), options);
    const auto [first, last] = g.segmentRows(0);
    const LodLevel coarsest = lodPyramid(options).back();
    ASSERT_LT(coarsest.tolerance_mm, 25.0);
    const std::vector<std::size_t> rows = decimatedRows(g, first, last, coarsest);
    const std::vector<double>& depth = g.table().depth_m;
    // Both edges of the breakout are kept (the rows either side of each step), and a row
    // inside it, so the coarse wall bulges over the whole metre.
    auto kept = [&](double top, double bottom) {
        for (std::size_t r : rows)
            if (depth[r] >= top && depth[r] <= bottom) return true;
        return false;
    };
    EXPECT_TRUE(kept(kBreakoutTop_m - 0.003, kBreakoutTop_m - 1e-9));
    EXPECT_TRUE(kept(kBreakoutTop_m, kBreakoutTop_m + 0.003));
    EXPECT_TRUE(kept(kBreakoutBottom_m - 0.003, kBreakoutBottom_m - 1e-9));
    EXPECT_TRUE(kept(kBreakoutBottom_m, kBreakoutBottom_m + 0.003));
    // The gauge hole around it needs a row per longest spacing only: 4,001 rows become few.
    EXPECT_LT(rows.size(), 30u);
}

TEST(LodLevelsTest, NeighbouringSegmentsShareTheirBoundaryRingAtEveryLevelPair) {
    // Every level ends a segment with the same full ring, so any two levels side by side
    // meet without a crack.
    GeometryOptions options;
    const WellGeometry g(std::make_shared<const SectionTable>(
                             makeSyntheticWell(syntheticProfile("example", 4.0, 0.0025))),
                         options);
    ASSERT_GE(g.segmentCount(), 3u);
    const std::size_t ring = static_cast<std::size_t>(g.sampler().samples());
    for (std::size_t s = 0; s + 1 < g.segmentCount(); ++s) {
        const SegmentMesh upper = g.buildSegment(s), lower = g.buildSegment(s + 1);
        ASSERT_EQ(upper.lastRow, lower.firstRow);
        for (std::size_t i = 0; i < upper.levels.size(); ++i)
            for (std::size_t j = 0; j < lower.levels.size(); ++j) {
                const auto& a = upper.levels[i].positions;
                const auto& b = lower.levels[j].positions;
                ASSERT_GE(a.size(), ring);
                ASSERT_GE(b.size(), ring);
                for (std::size_t k = 0; k < ring; ++k)
                    ASSERT_EQ(a[a.size() - ring + k], b[k])
                        << "segments " << s << "/" << s + 1 << " levels " << i << "/" << j
                        << " vertex " << k;
            }
    }
}

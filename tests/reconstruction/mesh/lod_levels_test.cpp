#include "reconstruction/mesh/lod_levels.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

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
            if (level.maxSpacing_m > 0.0 && b > a + 1) {
                EXPECT_LE(depth[b] - depth[a], level.maxSpacing_m + 1e-9);
            }
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

namespace {
// Triangles of the strips in indices [begin, end) (each strip ended by -1).
std::size_t stripTriangles(const std::vector<std::int32_t>& indices, std::size_t begin,
                           std::size_t end) {
    std::size_t triangles = 0, run = 0;
    for (std::size_t i = begin; i < end; ++i)
        if (indices[i] < 0) {
            triangles += run >= 3 ? run - 2 : 0;
            run = 0;
        } else {
            ++run;
        }
    return triangles;
}

// Rings of `points` vertices in a mesh built ring by ring.
std::size_t rings(const Mesh& mesh, std::size_t points) {
    return mesh.positions.size() / points;
}
}  // namespace

TEST(LodLevelsTest, FullDetailPartsTileLevelZeroAndEndOnItsRings) {
    const WellGeometry g(breakoutWell(), GeometryOptions{});
    const std::size_t ring = static_cast<std::size_t>(g.sampler().samples());
    for (std::size_t s = 0; s < g.segmentCount(); ++s) {
        const SegmentMesh segment = g.buildSegment(s);
        const Mesh& full = segment.levels.front();
        ASSERT_EQ(segment.parts.size(), 4u) << s;
        EXPECT_FLOAT_EQ(segment.partError_mm, static_cast<float>(g.options().shapeTolerance_mm));
        EXPECT_EQ(segment.parts.front().firstRow, segment.firstRow);
        EXPECT_EQ(segment.parts.back().lastRow, segment.lastRow);
        EXPECT_EQ(segment.parts.front().stripBegin, 0u);
        EXPECT_EQ(segment.parts.back().stripEnd, full.stripIndices.size());
        std::size_t triangles = 0;
        for (std::size_t p = 0; p < segment.parts.size(); ++p) {
            const DetailPart& part = segment.parts[p];
            if (p > 0) {
                EXPECT_EQ(part.firstRow, segment.parts[p - 1].lastRow);
                EXPECT_EQ(part.stripBegin, segment.parts[p - 1].stripEnd);
            }
            // A quarter of the segment, give or take a row; one strip per pair of rows.
            EXPECT_NEAR(g.table().depth_m[part.lastRow] - g.table().depth_m[part.firstRow], 0.25,
                        0.003);
            const std::size_t partTriangles =
                stripTriangles(full.stripIndices, part.stripBegin, part.stripEnd);
            EXPECT_EQ(partTriangles, (part.lastRow - part.firstRow) * 2 * ring);
            triangles += partTriangles;
            // The reduced copy begins and ends on level 0's rings of the same rows, so a
            // part meets its neighbours without a crack whichever copy each shows.
            const auto& reduced = part.reduced.positions;
            ASSERT_GE(reduced.size(), 2 * ring);
            const std::size_t a = (part.firstRow - segment.firstRow) * ring,
                              b = (part.lastRow - segment.firstRow) * ring;
            for (std::size_t k = 0; k < ring; ++k) {
                ASSERT_EQ(reduced[k], full.positions[a + k]) << s << "/" << p;
                ASSERT_EQ(reduced[reduced.size() - ring + k], full.positions[b + k])
                    << s << "/" << p;
            }
            EXPECT_LT(part.reduced.triangleCount(), partTriangles);
            // Its bounding sphere holds every vertex of the part.
            for (std::size_t v = a; v < b + ring; ++v)
                ASSERT_LE(glm::length(full.positions[v] - part.centre), part.radius + 1e-4f);
        }
        EXPECT_EQ(triangles, full.triangleCount());
    }
    // In the gauge hole a reduced part keeps a section per 5 cm; where the 1 m breakout
    // starts (5.2 m, in segment 5's first part) it keeps the rows either side of the step.
    const SegmentMesh gauge = g.buildSegment(2), breakout = g.buildSegment(5);
    for (const DetailPart& part : gauge.parts) EXPECT_LE(rings(part.reduced, ring), 7u);
    const DetailPart& step = breakout.parts[0];
    ASSERT_LT(g.table().depth_m[step.firstRow], kBreakoutTop_m);
    ASSERT_GT(g.table().depth_m[step.lastRow], kBreakoutTop_m);
    auto ringAt = [&](const Mesh& mesh, double depth) {  // scene y is minus the depth
        for (std::size_t v = 0; v < mesh.positions.size(); v += ring)
            if (std::abs(mesh.positions[v].y + depth) < 1e-4) return true;
        return false;
    };
    EXPECT_TRUE(ringAt(step.reduced, kBreakoutTop_m - 0.0025));
    EXPECT_TRUE(ringAt(step.reduced, kBreakoutTop_m));
    float widest = 0.0f;  // the breakout's arms reach 25 mm further in the reduced copy too
    for (std::size_t v = 0; v < step.reduced.positions.size(); ++v) {
        const glm::vec3 p = step.reduced.positions[v];
        widest = std::max(widest, std::hypot(p.x, p.z));
    }
    EXPECT_NEAR(widest, (8.5 * 25.4 / 2.0 + 25.0) / 1000.0, 0.002);
}

TEST(LodLevelsTest, SectionRingIsTheDrawnCircleAboutTheToolAxisAndScalesWithTheExaggeration) {
    const auto table = breakoutWell();
    const WellGeometry g(table, GeometryOptions{});
    const std::size_t row = 100;  // 0.25 m: gauge, every arm the same
    const double radius_m = table->radii(row)[0] / 1000.0;
    const glm::dvec3 axis = toScene(g.centre(row));
    const std::vector<glm::vec3> ring = sectionRing(g, row);
    ASSERT_EQ(ring.size(), static_cast<std::size_t>(g.sampler().samples()));
    for (const glm::vec3& p : ring) EXPECT_NEAR(glm::distance(glm::dvec3(p), axis), radius_m, 1e-5);

    GeometryOptions wide;
    wide.radialExaggeration = 10.0;
    const WellGeometry drawn(table, wide);
    for (const glm::vec3& p : sectionRing(drawn, row))
        EXPECT_NEAR(glm::distance(glm::dvec3(p), axis), 10.0 * radius_m, 1e-4);
    EXPECT_TRUE(sectionRing(g, table->rowCount()).empty());  // past the log: nothing
}

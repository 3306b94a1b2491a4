#include "reconstruction/mesh/lod_tree.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vector_relational.hpp>

#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_geometry.h"

using namespace caliper3d::reconstruction;
using caliper3d::io::SectionTable;

namespace {

// The example well (a breakout, a washout, a build from 100 m) over `length_m`, with rows
// `step_m` apart and a stretch without data from 40 to 41.5 m.
std::shared_ptr<const SectionTable> exampleWell(double length_m, double step_m) {
    SectionTable t = makeSyntheticWell(syntheticProfile("example", length_m, step_m));
    for (std::size_t r = 0; r < t.rowCount(); ++r)
        if (t.depth_m[r] >= 40.0 && t.depth_m[r] < 41.5)
            for (int a = 0; a < t.armCount; ++a)
                t.radii(r)[a] = std::numeric_limits<double>::quiet_NaN();
    return std::make_shared<const SectionTable>(std::move(t));
}

double pointToTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                       const glm::dvec3& c) {
    // Closest point on a triangle (Ericson, Real-Time Collision Detection, 5.1.5).
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return glm::length(p - a);
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return glm::length(p - b);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return glm::length(p - (a + ab * (d1 / (d1 - d3))));
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return glm::length(p - c);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return glm::length(p - (a + ac * (d2 / (d2 - d6))));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return glm::length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
    const double denom = 1.0 / (va + vb + vc);
    return glm::length(p - (a + ab * (vb * denom) + ac * (vc * denom)));
}

// The triangles of a mesh with their bounding boxes, to measure distances to it.
struct Triangles {
    explicit Triangles(const Mesh& mesh) {
        const std::vector<std::int32_t>& s = mesh.stripIndices;
        for (std::size_t i = 0; i + 2 < s.size(); ++i) {
            if (s[i] < 0 || s[i + 1] < 0 || s[i + 2] < 0) continue;
            Triangle t;
            for (int k = 0; k < 3; ++k) t.corner[k] = glm::dvec3(mesh.positions[s[i + k]]);
            t.lo = glm::min(t.corner[0], glm::min(t.corner[1], t.corner[2]));
            t.hi = glm::max(t.corner[0], glm::max(t.corner[1], t.corner[2]));
            all.push_back(t);
        }
    }
    // Distance from `p` to the nearest triangle, or `reach` when none is nearer than that
    // (the boxes then skip most triangles).
    double distance(const glm::dvec3& p, double reach) const {
        double best = reach;
        for (const Triangle& t : all) {
            if (glm::any(glm::lessThan(p, t.lo - best)) ||
                glm::any(glm::greaterThan(p, t.hi + best)))
                continue;
            best = std::min(best, pointToTriangle(p, t.corner[0], t.corner[1], t.corner[2]));
        }
        return best;
    }
    struct Triangle {
        glm::dvec3 corner[3];
        glm::dvec3 lo, hi;
    };
    std::vector<Triangle> all;
};

}  // namespace

TEST(LodTreeTest, SpansOfEachDepthCoverEverySegmentOnceInOrder) {
    EXPECT_EQ(lodTreeDepth(1), 1);
    EXPECT_EQ(lodTreeDepth(16), 1);
    EXPECT_EQ(lodTreeDepth(17), 2);
    EXPECT_EQ(lodTreeDepth(256), 2);
    EXPECT_EQ(lodTreeDepth(257), 3);
    EXPECT_EQ(lodTreeDepth(4000), 3);
    for (std::size_t segments : {1u, 15u, 16u, 17u, 300u, 4000u}) {
        for (int depth = 1; depth <= lodTreeDepth(segments); ++depth) {
            std::size_t next = 0;
            for (std::size_t i = 0; i < spanCount(depth, segments); ++i) {
                const auto [first, last] = spanSegments(depth, i, segments);
                EXPECT_EQ(first, next) << segments << " " << depth << " " << i;
                EXPECT_GE(last, first);
                next = last + 1;
            }
            EXPECT_EQ(next, segments) << segments << " " << depth;
        }
        EXPECT_EQ(spanCount(lodTreeDepth(segments), segments), 1u);  // one root
    }
}

TEST(LodTreeTest, EverySpanOfEveryDepthIsBuiltWithItsRowsAndAGrowingError) {
    GeometryOptions options;
    const WellGeometry g(exampleWell(300.0, 0.01), options);
    ASSERT_EQ(g.segmentCount(), 300u);
    const std::vector<SpanMesh> spans = buildSpanMeshes(g);
    // 19 spans of 16 segments, 2 of 256, the root.
    ASSERT_EQ(spans.size(), 19u + 2u + 1u);
    float previousDepthError = 0.0f;
    for (int depth = 1; depth <= 3; ++depth) {
        float largest = 0.0f;
        for (const SpanMesh& span : spans) {
            if (span.depth != depth) continue;
            const auto [s0, s1] = spanSegments(depth, span.index, g.segmentCount());
            EXPECT_EQ(span.firstSegment, s0);
            EXPECT_EQ(span.lastSegment, s1);
            EXPECT_EQ(span.firstRow, g.segmentRows(s0).first);
            EXPECT_EQ(span.lastRow, g.segmentRows(s1).second);
            EXPECT_GT(span.mesh.triangleCount(), 0u);
            largest = std::max(largest, span.error_mm);
        }
        EXPECT_GT(largest, previousDepthError) << depth;
        previousDepthError = largest;
    }
}

TEST(LodTreeTest, AMergedMeshIsWithinItsErrorOfEverySectionItDraws) {
    // Every 7th row's finest ring (the full spline, as level 0 draws it) lies within the span's
    // stated error of the span's merged mesh, through the breakout, the washout, the build and
    // beside the stretch without data.
    // Drawn true to size, and 20 times larger as a picture of a long well draws it.
    for (const double exaggeration : {1.0, 20.0}) {
        GeometryOptions options;
        options.radialExaggeration = exaggeration;
        const WellGeometry g(exampleWell(300.0, 0.02), options);
        for (const SpanMesh& span : buildSpanMeshes(g)) {
            const Triangles triangles(span.mesh);
            const double allowed_m = (span.error_mm + 0.5) / 1000.0;
            double worst = 0.0;
            for (std::size_t r = span.firstRow; r <= span.lastRow; r += 7) {
                if (!g.measured(r)) continue;
                for (const glm::vec3& p : sectionRing(g, r))
                    worst = std::max(worst, triangles.distance(glm::dvec3(p), 1.01 * allowed_m));
            }
            EXPECT_LE(worst, allowed_m)
                << "x" << exaggeration << " span " << span.depth << "/" << span.index;
        }
    }
}

TEST(LodTreeTest, SpansAndSegmentLevelsEndOnTheSameRingsSoNoCrackOpens) {
    // A span meets its neighbour, and a segment at any level meets a span, on the shared row's
    // full ring, bit for bit: whichever pair of levels the two sides show, there is no crack.
    GeometryOptions options;
    options.radialExaggeration = 5.0;
    const WellGeometry g(exampleWell(300.0, 0.02), options);
    const auto samples = static_cast<std::size_t>(g.sampler().samples());
    auto ringAt = [&](const Mesh& mesh, bool start) {
        const std::size_t from = start ? 0 : mesh.positions.size() - samples;
        return std::vector<glm::vec3>(
            mesh.positions.begin() + static_cast<std::ptrdiff_t>(from),
            mesh.positions.begin() + static_cast<std::ptrdiff_t>(from + samples));
    };
    std::size_t checked = 0;
    for (const SpanMesh& span : buildSpanMeshes(g)) {
        ASSERT_TRUE(g.measured(span.firstRow) && g.measured(span.lastRow));
        EXPECT_EQ(ringAt(span.mesh, true), sectionRing(g, span.firstRow));
        EXPECT_EQ(ringAt(span.mesh, false), sectionRing(g, span.lastRow));
        ++checked;
    }
    for (std::size_t s = 0; s < g.segmentCount(); s += 37) {
        const SegmentMesh segment = buildSegmentMesh(g, s);
        for (const Mesh& level : segment.levels) {
            EXPECT_EQ(ringAt(level, true), sectionRing(g, segment.firstRow)) << s;
            EXPECT_EQ(ringAt(level, false), sectionRing(g, segment.lastRow)) << s;
        }
    }
    EXPECT_EQ(checked, 22u);
}

TEST(LodTreeTest, AStretchWithoutDataIsAGapInEveryMergedMesh) {
    GeometryOptions options;
    const WellGeometry g(exampleWell(300.0, 0.02), options);
    const std::vector<double>& depth = g.table().depth_m;
    for (const SpanMesh& span : buildSpanMeshes(g)) {
        if (depth[span.lastRow] < 40.0 || depth[span.firstRow] > 41.5) continue;
        // No vertex inside the gap, and no strip crosses it: every triangle's corners lie on
        // one side of it (the scene's y is up, depth grows downwards: y falls).
        const double gapTop = -40.0, gapBottom = -41.5;  // y at the gap's ends (vertical there)
        const std::vector<std::int32_t>& s = span.mesh.stripIndices;
        for (std::size_t i = 0; i + 2 < s.size(); ++i) {
            if (s[i] < 0 || s[i + 1] < 0 || s[i + 2] < 0) continue;
            bool above = false, below = false;
            for (std::size_t k = i; k < i + 3; ++k) {
                const float y = span.mesh.positions[static_cast<std::size_t>(s[k])].y;
                above = above || y > gapTop - 0.05;
                below = below || y < gapBottom + 0.05;
            }
            EXPECT_FALSE(above && below) << "span " << span.depth << "/" << span.index;
        }
    }
}

TEST(LodTreeTest, ASpanOfAnUnchangingHoleHasNoErrorButItsPolygonsAndTheToolsTurn) {
    // A vertical hole at gauge: leaving rows out changes nothing, so a span's error is the
    // chord error of its six-sided rings alone (measured, not the tolerance the rows were kept
    // to), and it switches in as soon as its polygon is small enough on the screen.
    GeometryOptions options;
    options.radialExaggeration = 50.0;
    SyntheticWellSpec spec = syntheticProfile("circle", 300.0, 0.02);
    spec.toolRotation_degPerM = 0.0;
    const WellGeometry still(std::make_shared<const SectionTable>(makeSyntheticWell(spec)),
                             options);
    const double drawn_mm = spec.bitSize_mm / 2.0 * options.radialExaggeration;
    const double chord_mm = chordError(drawn_mm, still.knotCount());
    const std::vector<SpanMesh> spans = buildSpanMeshes(still);
    ASSERT_EQ(spans.size(), 22u);
    for (const SpanMesh& span : spans)
        EXPECT_NEAR(span.error_mm, chord_mm, 0.001 * drawn_mm) << span.depth << "/" << span.index;

    // A tool turning 2 degrees a metre: the straight edges between kept rings cut inside the
    // wall by up to r (1 - cos(turn / 2)) at each depth, r the drawn radius bound
    // (2F - 1) r, the turn at most the rate times the depth's longest spacing.
    spec.toolRotation_degPerM = 2.0;
    const WellGeometry turning(std::make_shared<const SectionTable>(makeSyntheticWell(spec)),
                               options);
    const double bound_mm = spec.bitSize_mm / 2.0 * (2.0 * options.radialExaggeration - 1.0);
    for (const SpanMesh& span : buildSpanMeshes(turning)) {
        double allowed_mm = chord_mm;
        for (int d = 1; d <= span.depth; ++d) {
            const double turn_rad =
                glm::radians(spec.toolRotation_degPerM *
                             spanLevel(options, turning.knotCount(), d).maxSpacing_m);
            allowed_mm += bound_mm * (1.0 - std::cos(turn_rad / 2.0));
        }
        EXPECT_GT(span.error_mm, chord_mm + 1.0) << span.depth << "/" << span.index;
        EXPECT_LE(span.error_mm, allowed_mm + 0.001 * drawn_mm) << span.depth << "/" << span.index;
    }

    // The example well's breakout and washout are errors the coarser spans do carry.
    const WellGeometry example(exampleWell(300.0, 0.02), options);
    float largest = 0.0f;
    for (const SpanMesh& span : buildSpanMeshes(example))
        largest = std::max(largest, span.error_mm);
    EXPECT_GT(largest, 2.0 * chord_mm);
}

namespace {

void expectSameMesh(const Mesh& a, const Mesh& b, const std::string& what) {
    EXPECT_EQ(a.positions, b.positions) << what;
    EXPECT_EQ(a.normals, b.normals) << what;
    EXPECT_EQ(a.colours, b.colours) << what;
    EXPECT_EQ(a.stripIndices, b.stripIndices) << what;
}

// `box` is the box of the points the strips of `levels` draw (empty with none).
void expectBoxOfStrips(const Box3& box, const std::vector<Mesh>& levels, const std::string& what) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (const Mesh& level : levels)
        for (const std::int32_t i : level.stripIndices)
            if (i >= 0) {
                lo = glm::min(lo, level.positions[static_cast<std::size_t>(i)]);
                hi = glm::max(hi, level.positions[static_cast<std::size_t>(i)]);
            }
    if (lo.x > hi.x) {
        EXPECT_TRUE(box.empty()) << what;
        return;
    }
    ASSERT_FALSE(box.empty()) << what;
    EXPECT_EQ(box.lo, lo) << what;
    EXPECT_EQ(box.hi, hi) << what;
}

}  // namespace

// A segment's box found from its plan (plannedSegmentBox) at every coarse level from the
// spline's to the pads' N-gon, true to size and exaggerated, across a stretch without data and
// past a row measured alone between two (a ring no strip joins, which draws nothing): exactly
// the box of the points its levels' strips draw.
TEST(LodTreeTest, APlannedSegmentIsBoundedByWhatItsStripsDraw) {
    SectionTable t = *exampleWell(300.0, 0.01);
    std::size_t alone = 0;
    for (std::size_t r = 0; r < t.rowCount(); ++r) {
        if (t.depth_m[r] < 60.0 || t.depth_m[r] >= 60.5) continue;
        if (alone == 0 && t.depth_m[r] >= 60.3) {
            alone = r;  // far out, so that the box would show it
            for (int a = 0; a < t.armCount; ++a) t.radii(r)[a] *= 3.0;
            continue;
        }
        for (int a = 0; a < t.armCount; ++a)
            t.radii(r)[a] = std::numeric_limits<double>::quiet_NaN();
    }
    ASSERT_GT(alone, 0u);
    const WellGeometry g(std::make_shared<const SectionTable>(std::move(t)), GeometryOptions{});
    for (const double exaggeration : {1.0, 20.0}) {
        SCOPED_TRACE("x" + std::to_string(exaggeration));
        const WellGeometry drawn = g.restyled(exaggeration, nullptr);
        const CoarsePlan plan = planCoarseMeshes(drawn, kFirstCoarseLevel, {exaggeration});
        std::size_t empty = 0;
        for (std::size_t s = 0; s < plan.segments.size(); ++s) {
            const SegmentMesh mesh = finishSegmentLevels(drawn, plan.segments[s], nullptr);
            ASSERT_EQ(mesh.levels.size(), 2u);
            const Box3 box = plannedSegmentBox(drawn, plan.segments[s], nullptr);
            expectBoxOfStrips(box, mesh.levels, "segment " + std::to_string(s));
            empty += box.empty() ? 1 : 0;
        }
        EXPECT_LT(empty, plan.segments.size() / 10);  // most segments draw a wall
    }
}

TEST(LodTreeTest, APlannedWellDrawsFromTheRowsItKeepsWhatTheWholeWellDraws) {
    // The coarse meshes planned on the whole well (a breakout, a washout, a build, a stretch
    // without data), then drawn from a copy holding only the rows the plan keeps: the same
    // meshes, errors and bounds as those built from the whole well, at each exaggeration the
    // plan lists; at another, the same meshes and errors no smaller than the whole well's.
    const WellGeometry g(exampleWell(300.0, 0.01), GeometryOptions{});
    const CoarsePlan plan = planCoarseMeshes(g, kFieldFirstCoarseLevel, {1.0, 20.0});
    const std::vector<std::size_t> rows = plan.rows();
    ASSERT_TRUE(std::is_sorted(rows.begin(), rows.end()));
    EXPECT_LT(rows.size(), g.table().rowCount() / 5);
    const WellGeometry held = g.sampled(rows);
    ASSERT_EQ(held.segmentCount(), g.segmentCount());
    for (const double exaggeration : {1.0, 20.0, 7.0}) {
        SCOPED_TRACE("x" + std::to_string(exaggeration));
        const CoarseMeshes whole =
            buildCoarseMeshes(g.restyled(exaggeration, nullptr), kFieldFirstCoarseLevel);
        const WellGeometry heldDrawn = held.restyled(exaggeration, nullptr);
        const CoarseMeshes drawn = buildCoarseMeshes(heldDrawn, plan, &rows, 1);
        ASSERT_EQ(drawn.segments.size(), whole.segments.size());
        for (std::size_t s = 0; s < whole.segments.size(); ++s) {
            const SegmentMesh &a = whole.segments[s], &b = drawn.segments[s];
            // Bounded, before it is built, by the box of what its strips draw.
            expectBoxOfStrips(plannedSegmentBox(heldDrawn, plan.segments[s], &rows), a.levels,
                              "segment " + std::to_string(s));
            EXPECT_EQ(b.firstRow, a.firstRow);
            EXPECT_EQ(b.lastRow, a.lastRow);
            EXPECT_EQ(b.top_m, a.top_m);
            EXPECT_EQ(b.fullDetailTriangles, a.fullDetailTriangles);
            EXPECT_EQ(b.levelError_mm, a.levelError_mm);
            EXPECT_EQ(b.maxRadius_m, a.maxRadius_m);
            EXPECT_EQ(b.centre, a.centre);
            EXPECT_EQ(b.radius, a.radius);
            ASSERT_EQ(b.levels.size(), a.levels.size());
            for (std::size_t l = 0; l < a.levels.size(); ++l)
                expectSameMesh(a.levels[l], b.levels[l], "segment " + std::to_string(s));
        }
        ASSERT_EQ(drawn.spans.size(), whole.spans.size());
        for (std::size_t i = 0; i < whole.spans.size(); ++i) {
            const SpanMesh &a = whole.spans[i], &b = drawn.spans[i];
            const std::string span = std::to_string(a.depth) + "/" + std::to_string(a.index);
            EXPECT_EQ(b.firstRow, a.firstRow) << span;
            EXPECT_EQ(b.lastRow, a.lastRow) << span;
            EXPECT_EQ(b.centre, a.centre) << span;
            EXPECT_EQ(b.maxRadius_m, a.maxRadius_m) << span;
            if (exaggeration == 7.0) {
                EXPECT_GE(b.error_mm, a.error_mm) << span;
                EXPECT_GE(b.radius, a.radius) << span;
            } else {
                EXPECT_EQ(b.error_mm, a.error_mm) << span;
                EXPECT_EQ(b.radius, a.radius) << span;
            }
            expectSameMesh(a.mesh, b.mesh, "span " + span);
        }
    }
}

TEST(LodTreeTest, AWellsPlanTakesEachRowsKnotsOnceAndDecidesAsEachPlanAlone) {
    // planCoarseMeshes takes each row's knots once for a span of depth 1 and its sixteen
    // segments: every segment planned alone (planSegmentLevels) and every span planned on its
    // own (buildSpanMeshes) decide the same rows, radii and errors, through a stretch without
    // data, a breakout and a washout, on six arms and on a 40-finger tool.
    SyntheticWellSpec fingers = syntheticProfile("example", 120.0, 0.01);
    fingers.armCount = 40;
    const std::vector<std::shared_ptr<const SectionTable>> tables = {
        exampleWell(300.0, 0.01), std::make_shared<const SectionTable>(makeSyntheticWell(fingers))};
    for (const auto& table : tables) {
        SCOPED_TRACE(std::to_string(table->armCount) + " arms");
        GeometryOptions options;
        options.radialExaggeration = 20.0;
        const WellGeometry g(table, options);
        const CoarsePlan plan = planCoarseMeshes(g, kFieldFirstCoarseLevel, {20.0}, 2);
        ASSERT_EQ(plan.segments.size(), g.segmentCount());
        for (std::size_t s = 0; s < g.segmentCount(); ++s) {
            const SegmentPlan alone =
                planSegmentLevels(g, s, kFieldFirstCoarseLevel, std::numeric_limits<int>::max());
            EXPECT_EQ(plan.segments[s].levelRows, alone.levelRows) << s;
            EXPECT_EQ(plan.segments[s].maxRadius_mm, alone.maxRadius_mm) << s;
            EXPECT_EQ(plan.segments[s].fullDetailTriangles, alone.fullDetailTriangles) << s;
        }
        const std::vector<SpanMesh> planned = buildPlannedSpans(g, plan);
        const std::vector<SpanMesh> own = buildSpanMeshes(g);
        ASSERT_EQ(planned.size(), own.size());
        for (std::size_t i = 0; i < own.size(); ++i) {
            const std::string span =
                std::to_string(own[i].depth) + "/" + std::to_string(own[i].index);
            EXPECT_EQ(planned[i].error_mm, own[i].error_mm) << span;
            EXPECT_EQ(planned[i].radius, own[i].radius) << span;
            EXPECT_EQ(planned[i].maxRadius_m, own[i].maxRadius_m) << span;
            expectSameMesh(planned[i].mesh, own[i].mesh, "span " + span);
        }
    }
}

namespace {
// What the span of a gauge hole with rows pushed off round measures where it keeps none of
// them (its kept rows all gauge): at each exaggeration F, the largest distance between a
// pushed row's polygon and the gauge polygon, each drawn F times larger about its own centroid
// (drawnRing, ringCentroid): |dc + F ds| over the pads, dc between the centroids, ds between
// the points about them; and the largest |dc| and |ds|. `pushes`: each row's push of each arm.
struct DrawnPadErrors {
    std::vector<double> at;  // at each of the factors
    double centroid = 0.0, shape = 0.0;
};
DrawnPadErrors drawnPadErrors(double gaugeRadius, const std::vector<std::vector<double>>& pushes,
                              const std::vector<double>& fs) {
    std::vector<glm::dvec2> gauge;
    drawnRing(std::vector<double>(6, gaugeRadius), 1.0, gauge);
    const glm::dvec2 gaugeCentroid = ringCentroid(gauge);
    DrawnPadErrors out;
    out.at.assign(fs.size(), 0.0);
    for (const std::vector<double>& by : pushes) {
        std::vector<double> radii(6);
        for (std::size_t a = 0; a < 6; ++a) radii[a] = gaugeRadius + by[a];
        std::vector<glm::dvec2> ring;
        drawnRing(radii, 1.0, ring);
        const glm::dvec2 centroid = ringCentroid(ring);
        const glm::dvec2 dc = centroid - gaugeCentroid;
        out.centroid = std::max(out.centroid, glm::length(dc));
        for (std::size_t j = 0; j < 6; ++j) {
            const glm::dvec2 ds = (ring[j] - centroid) - (gauge[j] - gaugeCentroid);
            out.shape = std::max(out.shape, glm::length(ds));
            for (std::size_t f = 0; f < fs.size(); ++f)
                out.at[f] = std::max(out.at[f], glm::length(dc + fs[f] * ds));
        }
    }
    return out;
}
}  // namespace

TEST(LodTreeTest, ASpansPadErrorIsTheDrawnDistanceBetweenTheRowsPolygonAndTheLine) {
    // A gauge hole with two rows pushed off round inside the tolerance of the first depth: the
    // span keeps neither, and its pads' error at each exaggeration F is the largest distance
    // between a pushed row's polygon and the gauge polygon, each drawn F times larger about
    // its own centroid (drawnRing, ringCentroid): |dc + F ds| over the pads, dc between the
    // centroids, ds between the points about them.
    SyntheticWellSpec spec = syntheticProfile("circle", 40.0, 0.02);
    spec.toolRotation_degPerM = 0.0;
    SectionTable t = makeSyntheticWell(spec);
    const std::vector<std::pair<double, std::vector<double>>> pushed = {
        {5.31, {9.0, 0.0, 0.0, 0.0, 0.0, 0.0}}, {11.17, {0.0, 4.0, -6.0, 0.0, 3.0, 0.0}}};
    for (const auto& [depth_m, by] : pushed) {
        const auto row = static_cast<std::size_t>(std::lround(depth_m / spec.step_m));
        for (int a = 0; a < t.armCount; ++a) t.radii(row)[a] += by[static_cast<std::size_t>(a)];
    }
    const WellGeometry g(std::make_shared<const SectionTable>(t), GeometryOptions{});
    const std::vector<double> fs = {1.0, 20.0};
    const CoarsePlan plan = planCoarseMeshes(g, kFieldFirstCoarseLevel, fs, 1);
    ASSERT_FALSE(plan.spans.empty());
    const SpanPlan& span = plan.spans.front();
    ASSERT_EQ(span.depth, 1);
    std::vector<std::vector<double>> pushes;
    for (const auto& [depth_m, by] : pushed) {
        const auto row = static_cast<std::size_t>(std::lround(depth_m / spec.step_m));
        ASSERT_FALSE(std::binary_search(span.rows.begin(), span.rows.end(), row)) << depth_m;
        pushes.push_back(by);
    }
    const DrawnPadErrors drawn = drawnPadErrors(spec.bitSize_mm / 2.0, pushes, fs);
    const std::vector<double>& expected = drawn.at;
    const double centroidWorst = drawn.centroid, shapeWorst = drawn.shape;
    ASSERT_GT(centroidWorst, 1.0);  // the pushed rows' centroids moved
    ASSERT_EQ(span.padError_mm.size(), fs.size());
    for (std::size_t f = 0; f < fs.size(); ++f)
        EXPECT_NEAR(span.padError_mm[f], expected[f], 1e-9 * expected[f]) << "x" << fs[f];
    EXPECT_NEAR(span.padCentroid_mm, centroidWorst, 1e-9);
    EXPECT_NEAR(span.padShape_mm, shapeWorst, 1e-9);
}

// Many rows pushed off round by different amounts, in random order of size along the span: the
// rows passed over as unable to raise the worst at any factor (the envelope of the factors'
// lines) never could. The pads' error at each of fourteen factors, listed out of order, is the
// largest drawn distance over every pushed row, as each polygon is drawn (drawnRing,
// ringCentroid).
TEST(LodTreeTest, ASpansPadErrorAtEveryFactorIsTheLargestOverEveryRow) {
    SyntheticWellSpec spec = syntheticProfile("circle", 40.0, 0.02);
    spec.toolRotation_degPerM = 0.0;
    SectionTable t = makeSyntheticWell(spec);
    std::mt19937 random(5);
    std::uniform_real_distribution<double> push(-0.3, 0.3);
    std::vector<std::pair<std::size_t, std::vector<double>>> pushed;
    for (std::size_t row = 20; row < 780; row += 7) {
        std::vector<double> by(6);
        // Pushes of every size: most small, a few large, anywhere along the span.
        const double scale = (row % 49 == 0) ? 2.5 : (row % 5 == 0 ? 0.2 : 1.0);  // up to 0.75 mm
        for (double& b : by) b = scale * push(random);
        pushed.emplace_back(row, by);
    }
    // A row moved off the axis whole (its centroid 3 mm away, its shape nearly round), and after
    // it one made oval about the axis (its centroid on the axis, its shape 1.2 mm off): the first
    // is the farther at x 1, the second at x 1000, where only the steepest factors' lines can
    // tell that it may raise their worst.
    std::vector<double> moved(6), oval(6);
    for (std::size_t a = 0; a < 6; ++a) {
        const double angle = glm::radians(60.0 * static_cast<double>(a));
        moved[a] = 3.0 * std::cos(angle - 0.4);
        oval[a] = 2.0 * std::cos(2.0 * angle);
    }
    pushed.emplace_back(101, moved);
    pushed.emplace_back(506, oval);  // between the random rows (20 + 7 k)
    std::sort(pushed.begin(), pushed.end());
    for (const auto& [row, by] : pushed)
        for (int a = 0; a < t.armCount; ++a) t.radii(row)[a] += by[static_cast<std::size_t>(a)];
    const WellGeometry g(std::make_shared<const SectionTable>(t), GeometryOptions{});
    const std::vector<double> fs = {30, 1, 1000, 3, 50, 7, 2, 300, 10, 500, 5, 100, 20, 200};
    const CoarsePlan plan = planCoarseMeshes(g, kFieldFirstCoarseLevel, fs, 1);
    ASSERT_FALSE(plan.spans.empty());
    const SpanPlan& span = plan.spans.front();
    ASSERT_EQ(span.depth, 1);
    std::vector<std::vector<double>> pushes;
    for (const auto& [row, by] : pushed) {
        if (row > span.lastRow) break;
        ASSERT_FALSE(std::binary_search(span.rows.begin(), span.rows.end(), row)) << row;
        pushes.push_back(by);
    }
    const std::size_t counted = pushes.size();
    const std::vector<double> expected = drawnPadErrors(spec.bitSize_mm / 2.0, pushes, fs).at;
    ASSERT_GT(counted, 50u);
    ASSERT_EQ(span.padError_mm.size(), fs.size());
    for (std::size_t f = 0; f < fs.size(); ++f)
        EXPECT_NEAR(span.padError_mm[f], expected[f], 1e-9 * expected[f]) << "x" << fs[f];
}

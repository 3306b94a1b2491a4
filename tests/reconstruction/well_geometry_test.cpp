#include "reconstruction/well_geometry.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include "reconstruction/path/course_dogleg.h"
#include "support/reconstruction_support.h"

#include "reconstruction/synthetic/synthetic_well.h"

using namespace caliper3d::reconstruction;

namespace {
std::shared_ptr<const caliper3d::io::SectionTable> circleWell(double length, double step) {
    return std::make_shared<const caliper3d::io::SectionTable>(
        makeSyntheticWell(syntheticProfile("circle", length, step)));
}
}  // namespace

TEST(WellGeometryTest, SegmentsCoverEveryRowAndShareBoundaries) {
    GeometryOptions options;
    options.segmentLength_m = 10.0;
    WellGeometry g(circleWell(35.0, 0.1), options);
    ASSERT_EQ(g.segmentCount(), 4u);  // 10 m segments over 35 m
    EXPECT_EQ(g.segmentRows(0).first, 0u);
    for (std::size_t s = 1; s < g.segmentCount(); ++s)
        EXPECT_EQ(g.segmentRows(s).first, g.segmentRows(s - 1).second);
    EXPECT_EQ(g.segmentRows(g.segmentCount() - 1).second, g.table().rowCount() - 1);
}

TEST(WellGeometryTest, FullLevelHasSplineRingsAndCoarseLevelsAreNGons) {
    GeometryOptions options;
    options.splinePoints = 48;
    options.segmentLength_m = 10.0;
    WellGeometry g(circleWell(10.0, 0.1), options);
    const SegmentMesh seg = g.buildSegment(0);
    ASSERT_EQ(seg.levels.size(), 4u);
    const std::size_t rings = seg.lastRow - seg.firstRow + 1;
    EXPECT_EQ(seg.levels[0].positions.size(), rings * 48);
    EXPECT_EQ(seg.levels[0].triangleCount(), (rings - 1) * 96);
    EXPECT_EQ(seg.fullDetailTriangles, seg.levels[0].triangleCount());
    // Fewer points per section at each step, the raw 6-gon last.
    EXPECT_EQ(seg.levels[1].positions.size() % 24, 0u);
    EXPECT_EQ(seg.levels[2].positions.size() % 12, 0u);
    EXPECT_EQ(seg.levels[3].positions.size() % 6, 0u);
    // A gauge circle is interpolated exactly: the coarse levels keep a section a longest spacing.
    EXPECT_LT(seg.levels[3].positions.size(), seg.levels[0].positions.size() / 8);
    for (std::size_t l = 1; l < seg.levels.size(); ++l)
        EXPECT_LT(seg.levels[l].triangleCount(), seg.levels[l - 1].triangleCount()) << l;
    // Errors grow level by level; full detail has none.
    ASSERT_EQ(seg.levelError_mm.size(), 4u);
    EXPECT_EQ(seg.levelError_mm[0], 0.0f);
    for (std::size_t l = 1; l < 4; ++l) EXPECT_GT(seg.levelError_mm[l], seg.levelError_mm[l - 1]);
}

TEST(WellGeometryTest, GaugeHoleVerticesLieAtBitRadiusAroundTheAxis) {
    GeometryOptions options;
    options.segmentLength_m = 10.0;
    WellGeometry g(circleWell(10.0, 0.5), options);
    const SegmentMesh seg = g.buildSegment(0);
    const Mesh& m = seg.levels[0];
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        const glm::vec3 p = m.positions[i];
        // Vertical hole at the origin: the axis is the scene's Y axis.
        EXPECT_NEAR(std::hypot(p.x, p.z), 0.21590f / 2, 1e-5f);
        // Normals point outward.
        EXPECT_GT(glm::dot(glm::vec2(m.normals[i].x, m.normals[i].z), glm::vec2(p.x, p.z)), 0.0f);
    }
    EXPECT_NEAR(m.positions.back().y, -10.0f, 1e-4f);
}

TEST(WellGeometryTest, MissingArmIsFilledFromNeighbours) {
    auto table = makeSyntheticWell(syntheticProfile("circle", 2.0, 0.5));
    table.radii(1)[2] = std::nan("");
    table.radii(2)[0] = -1.0;
    WellGeometry g(std::make_shared<const caliper3d::io::SectionTable>(table), GeometryOptions{});
    for (double r : repairedRadii(g, 1)) EXPECT_NEAR(r, 215.9 / 2, 1e-9);
    for (double r : repairedRadii(g, 2)) EXPECT_NEAR(r, 215.9 / 2, 1e-9);
}

TEST(WellGeometryTest, RejectsDepthsThatDoNotIncrease) {
    auto table = makeSyntheticWell(syntheticProfile("circle", 2.0, 0.5));
    table.depth_m[2] = table.depth_m[1];
    EXPECT_THROW(
        WellGeometry(std::make_shared<const caliper3d::io::SectionTable>(table), GeometryOptions{}),
        std::invalid_argument);
}

TEST(WellGeometryTest, RadialExaggerationScalesTheDrawnRadiusOnly) {
    GeometryOptions options;
    options.radialExaggeration = 20.0;
    options.segmentLength_m = 10.0;
    WellGeometry g(circleWell(10.0, 0.5), options);
    const SegmentMesh segment = g.buildSegment(0);
    const Mesh& m = segment.levels[0];
    for (const glm::vec3& p : m.positions)
        EXPECT_NEAR(std::hypot(p.x, p.z), 20.0f * 0.21590f / 2, 1e-4f);
    for (double r : repairedRadii(g, 3)) EXPECT_NEAR(r, 215.9 / 2, 1e-9);  // the data stay true
    EXPECT_NEAR(m.positions.back().y, -10.0f, 1e-4f);                      // and so does the path
}

namespace {
// The path and frames computed the plain way: one station per row with nulls
// carried forward, one sequential minimum-curvature pass, frames from the angles.
void expectSequentialGeometry(const WellGeometry& g) {
    const caliper3d::io::SectionTable& t = g.table();
    std::vector<SurveyStation> stations(t.rowCount());
    double inc = 0.0, azi = 0.0;
    for (std::size_t i = 0; i < t.rowCount(); ++i) {
        if (i < t.devi_deg.size() && std::isfinite(t.devi_deg[i])) inc = t.devi_deg[i];
        if (i < t.hazi_deg.size() && std::isfinite(t.hazi_deg[i])) azi = t.hazi_deg[i];
        stations[i] = {t.depth_m[i], inc, azi};
    }
    std::vector<PathPoint> expected = minimumCurvaturePath(stations);
    setCourseLengthDls(expected);  // dogleg severity over the 30 m course, as the geometry's
    ASSERT_EQ(g.path().size(), expected.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const PathPoint &p = g.path()[i], &q = expected[i];
        differ += p.md != q.md || p.north != q.north || p.east != q.east || p.tvd != q.tvd ||
                  p.inc_deg != q.inc_deg || p.azi_deg != q.azi_deg ||
                  p.dogleg_deg != q.dogleg_deg || p.dls_degPer30m != q.dls_degPer30m;
        const SectionFrame f =
            g.orientation(i) == WellGeometry::Orientation::RelativeBearing
                ? frameFromRelativeBearing(q.inc_deg, q.azi_deg, t.rb_deg[i])
                : frameFromPadAzimuth(q.inc_deg, q.azi_deg,
                                      std::isfinite(t.p1az_deg[i]) ? t.p1az_deg[i] : 0.0);
        differ += f.tangent != g.frame(i).tangent || f.arm1 != g.frame(i).arm1 ||
                  f.side != g.frame(i).side;
    }
    EXPECT_EQ(differ, 0u);  // bit for bit, not merely within 1e-9 m
}
}  // namespace

TEST(WellGeometryTest, ParallelPathAndFramesAreTheSequentialOnesBitForBit) {
    // 13 blocks of rows; nulls in DEVI and HAZI across a block boundary and at the top.
    auto spec = syntheticProfile("example", 120.0, 0.0025);
    spec.kickoff_m = 5.0;
    spec.turnRate_degPer30m = 2.0;
    auto table = makeSyntheticWell(spec);
    for (std::size_t i = 0; i < 10; ++i) table.devi_deg[i] = std::nan("");
    for (std::size_t i = 4000; i < 8300; ++i) table.devi_deg[i] = table.hazi_deg[i] = std::nan("");
    for (std::size_t i = 20000; i < 30000; i += 3) table.rb_deg[i] = std::nan("");
    auto shared = std::make_shared<const caliper3d::io::SectionTable>(table);
    GeometryOptions options;
    options.steepInclination_deg = 2.0;  // frames from RB, and from P1AZ where RB is null
    for (int threads : {1, 2, 3}) {
        options.threads = threads;
        const WellGeometry g(shared, options);
        expectSequentialGeometry(g);
    }
}

TEST(WellGeometryTest, PathFromASurveyGetsItsFramesInParallelToo) {
    auto table = std::make_shared<const caliper3d::io::SectionTable>(
        makeSyntheticWell(syntheticProfile("circle", 30.0, 0.0025)));
    GeometryOptions options;
    options.survey = {{0.0, 0.0, 0.0}, {10.0, 5.0, 30.0}, {30.0, 20.0, 40.0}};
    const WellGeometry one(table, options);
    options.threads = 2;
    const WellGeometry two(table, options);
    for (std::size_t i = 0; i < table->rowCount(); ++i) {
        ASSERT_EQ(one.path()[i].tvd, two.path()[i].tvd);
        ASSERT_EQ(one.frame(i).arm1, two.frame(i).arm1);
        ASSERT_EQ(one.frame(i).tangent, holeTangent(one.path()[i].inc_deg, one.path()[i].azi_deg));
    }
}

// Design section 3: arm 1 from P1AZ in near-vertical holes, from RB (relative to the
// high side) in steep ones (above steepInclination_deg, default 15) or where P1AZ is
// missing; P1AZ where RB is missing; neither: arm 1 north, counted as unoriented.
TEST(WellGeometryTest, ArmOneComesFromPadAzimuthOrRelativeBearingByInclination) {
    caliper3d::io::SectionTable t;
    t.armCount = 3;
    // Constant hole direction per row group: 10 deg (shallow) then 20 deg (steep), azimuth 40.
    // P1AZ is written 30 deg away from what HAZI + RB give, so the two sources differ visibly.
    struct Row {
        double inc, p1az, rb;
    };
    const double kNaN = std::nan("");
    const std::vector<Row> rows = {{10, 100, 30},    {10, kNaN, 30}, {10, 100, kNaN},
                                   {10, kNaN, kNaN}, {20, 100, 30},  {20, 100, kNaN}};
    for (std::size_t i = 0; i < rows.size(); ++i) {
        t.depth_m.push_back(100.0 + i);
        for (int k = 0; k < 3; ++k) t.radius_mm.push_back(100.0);
        t.devi_deg.push_back(rows[i].inc);
        t.hazi_deg.push_back(40.0);
        t.p1az_deg.push_back(rows[i].p1az);
        t.rb_deg.push_back(rows[i].rb);
    }
    GeometryOptions options;
    options.survey = {
        {0.0, 10.0, 40.0}, {103.5, 10.0, 40.0}, {103.6, 20.0, 40.0}, {200.0, 20.0, 40.0}};
    const WellGeometry g(std::make_shared<const caliper3d::io::SectionTable>(t), options);
    using O = WellGeometry::Orientation;
    const O expected[] = {O::PadAzimuth, O::RelativeBearing, O::PadAzimuth,
                          O::Unoriented, O::RelativeBearing, O::PadAzimuth};
    for (std::size_t i = 0; i < rows.size(); ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(g.orientation(i), expected[i]);
        const PathPoint& p = g.path()[i];
        ASSERT_NEAR(p.inc_deg, rows[i].inc, 1e-9);
        const SectionFrame want =
            expected[i] == O::RelativeBearing
                ? frameFromRelativeBearing(p.inc_deg, p.azi_deg, rows[i].rb)
                : frameFromPadAzimuth(p.inc_deg, p.azi_deg,
                                      expected[i] == O::Unoriented ? 0.0 : rows[i].p1az);
        EXPECT_LT(glm::length(g.frame(i).arm1 - want.arm1), 1e-9);
    }
    // The two sources really differ by the 30 deg written into P1AZ.
    const SectionFrame a = frameFromPadAzimuth(10.0, 40.0, 100.0),
                       b = frameFromRelativeBearing(10.0, 40.0, 30.0);
    EXPECT_GT(glm::length(a.arm1 - b.arm1), 0.4);
    // A lower threshold turns the shallow rows to RB too.
    options.steepInclination_deg = 5.0;
    const WellGeometry low(std::make_shared<const caliper3d::io::SectionTable>(t), options);
    EXPECT_EQ(low.orientation(0), O::RelativeBearing);
}

TEST(WellGeometryTest, ACancelStopsThePathAndFramesWithGeometryCancelled) {
    std::atomic<bool> cancel{true};
    GeometryOptions options;
    options.cancel = &cancel;
    EXPECT_THROW(WellGeometry(circleWell(20.0, 0.01), options), GeometryCancelled);
    cancel = false;
    EXPECT_EQ(WellGeometry(circleWell(20.0, 0.01), options).path().size(), 2001u);
}

// A well held by a sample of its rows: every k-th row, the first and the last, each exactly
// where, how oriented and whether measured as in the whole well; a small well whole.
TEST(WellGeometryTest, ASampleKeepsItsRowsPlacedExactlyAsTheWholeWell) {
    auto table = std::make_shared<caliper3d::io::SectionTable>(
        makeSyntheticWell(syntheticProfile("example", 300.0, 0.01)));
    // A stretch without data, which the sample must say too.
    for (std::size_t row = 10000; row < 12000; ++row)
        for (int a = 0; a < table->armCount; ++a) table->radii(row)[a] = caliper3d::io::kNaN;
    const WellGeometry whole(table, GeometryOptions{});
    const std::size_t rows = whole.table().rowCount();
    ASSERT_EQ(rows, 30001u);
    const WellGeometry sample = whole.sampled(1000);
    const std::size_t stride = 30;                // 30001 / 1000
    ASSERT_EQ(sample.table().rowCount(), 1001u);  // rows 0, 30, ... 30000 (the last)
    EXPECT_EQ(sample.table().depth_m.back(), whole.table().depth_m.back());
    EXPECT_EQ(sample.table().armCount, whole.table().armCount);
    EXPECT_EQ(sample.table().source, whole.table().source);
    std::size_t measured = 0;
    for (std::size_t k = 0; k < sample.table().rowCount(); ++k) {
        const std::size_t row = std::min(k * stride, rows - 1);
        EXPECT_EQ(sample.table().depth_m[k], whole.table().depth_m[row]) << k;
        EXPECT_EQ(sample.path()[k].north, whole.path()[row].north) << k;
        EXPECT_EQ(sample.path()[k].east, whole.path()[row].east) << k;
        EXPECT_EQ(sample.path()[k].tvd, whole.path()[row].tvd) << k;
        EXPECT_EQ(sample.path()[k].inc_deg, whole.path()[row].inc_deg) << k;
        EXPECT_EQ(sample.orientation(k), whole.orientation(row)) << k;
        EXPECT_EQ(sample.measured(k), whole.measured(row)) << k;
        for (int a = 0; a < whole.table().armCount; ++a) {
            const double r = whole.table().radii(row)[a];
            if (std::isnan(r))
                EXPECT_TRUE(std::isnan(sample.table().radii(k)[a]));
            else
                EXPECT_EQ(sample.table().radii(k)[a], r);
        }
        measured += sample.measured(k) ? 1 : 0;
    }
    EXPECT_EQ(sample.measuredRows(), measured);
    EXPECT_LT(measured, sample.table().rowCount());  // the stretch without data is sampled too
    // Its segments cover the sample as a well's do; its colouring is not carried.
    EXPECT_EQ(sample.segmentRows(0).first, 0u);
    EXPECT_EQ(sample.segmentRows(sample.segmentCount() - 1).second, sample.table().rowCount() - 1);
    EXPECT_FALSE(sample.options().colouring);
    // Where the stride does not reach the last row, the last row ends the sample all the same.
    const WellGeometry seven = whole.sampled(7);  // rows 0, 4285, ... 29995, then 30000
    ASSERT_EQ(seven.table().rowCount(), 9u);
    EXPECT_EQ(seven.table().depth_m[7], whole.table().depth_m[29995]);
    EXPECT_EQ(seven.path().back().tvd, whole.path().back().tvd);
    // A well of no more rows than asked is kept whole.
    EXPECT_EQ(whole.sampled(rows).table().rowCount(), rows);
}

// A well held by rows chosen by name: those of its segments' ends cut it as the whole well is
// cut, and those of its path line draw the same line.
TEST(WellGeometryTest, AWellHeldByItsSegmentEndsAndPathLineRowsKeepsItsSegmentsAndLine) {
    const WellGeometry whole(std::make_shared<const caliper3d::io::SectionTable>(
                                 makeSyntheticWell(syntheticProfile("example", 300.0, 0.01))),
                             GeometryOptions{});
    std::vector<std::size_t> rows = pathLineRows(whole, 2.5);
    for (std::size_t s = 0; s < whole.segmentCount(); ++s) {
        rows.push_back(whole.segmentRows(s).first);
        rows.push_back(whole.segmentRows(s).second);
    }
    for (std::size_t row = 0; row < whole.table().rowCount(); row += 997) rows.push_back(row);
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    const WellGeometry held = whole.sampled(rows);
    ASSERT_EQ(held.table().rowCount(), rows.size());
    ASSERT_LT(rows.size(), whole.table().rowCount() / 10);
    ASSERT_EQ(held.segmentCount(), whole.segmentCount());
    for (std::size_t s = 0; s < whole.segmentCount(); ++s) {
        EXPECT_EQ(rows[held.segmentRows(s).first], whole.segmentRows(s).first) << s;
        EXPECT_EQ(rows[held.segmentRows(s).second], whole.segmentRows(s).second) << s;
    }
    const std::vector<glm::vec3> line = pathLine(whole, 2.5);
    EXPECT_EQ(pathLine(held, 2.5), line);
    EXPECT_EQ(line.size(), pathLineRows(whole, 2.5).size());
    EXPECT_EQ(everyKthRow(10, 3), (std::vector<std::size_t>{0, 3, 6, 9}));
    EXPECT_EQ(everyKthRow(11, 3), (std::vector<std::size_t>{0, 3, 6, 9, 10}));
}

namespace {

// The distance from `p` to the line through `kept` points of `line`.
float distanceToKept(const glm::vec3& p, const std::vector<glm::vec3>& line,
                     const std::vector<std::size_t>& kept) {
    float best = 1e30f;
    for (std::size_t k = 0; k + 1 < kept.size(); ++k) {
        const glm::vec3 a = line[kept[k]], ab = line[kept[k + 1]] - a;
        const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
        best = std::min(best, glm::length(p - (a + t * ab)));
    }
    return best;
}

}  // namespace

// A path line made coarser (simplifiedLine, Douglas and Peucker): a straight line keeps its
// ends; a build of 90 degrees over a 300 m radius keeps every point within the tolerance of
// the line kept, says how far the furthest one is, and keeps fewer points for a wider
// tolerance; a point standing out is kept.
TEST(WellGeometryTest, ACoarserPathLineKeepsEveryPointWithinItsTolerance) {
    std::vector<glm::vec3> straight;
    for (int i = 0; i <= 1000; ++i) straight.emplace_back(0.0f, -static_cast<float>(i), 0.0f);
    float error = -1.0f;
    EXPECT_EQ(simplifiedLine(straight, 0.25f, &error), (std::vector<std::size_t>{0, 1000}));
    EXPECT_LT(error, 1e-3f);  // (float rounding at a kilometre)

    std::vector<glm::vec3> build;
    for (int i = 0; i <= 471; ++i) {  // a metre apart on a quarter circle of 300 m
        const double a = i / 300.0;
        build.emplace_back(static_cast<float>(300.0 * (1.0 - std::cos(a))),
                           static_cast<float>(-300.0 * std::sin(a)), 0.0f);
    }
    std::size_t previous = build.size() + 1;
    for (const float tolerance : {0.05f, 0.25f, 1.0f}) {
        SCOPED_TRACE(tolerance);
        const std::vector<std::size_t> kept = simplifiedLine(build, tolerance, &error);
        ASSERT_GE(kept.size(), 2u);
        EXPECT_EQ(kept.front(), 0u);
        EXPECT_EQ(kept.back(), build.size() - 1);
        EXPECT_TRUE(std::is_sorted(kept.begin(), kept.end()));
        EXPECT_LT(kept.size(), previous);
        previous = kept.size();
        float worst = 0.0f;
        for (const glm::vec3& p : build) worst = std::max(worst, distanceToKept(p, build, kept));
        EXPECT_LE(worst, tolerance);
        EXPECT_NEAR(error, worst, 1e-4f);
        // The chord of a circle strays r (1 - cos(half its angle)): a tenth of the arc's
        // points or fewer at 0.25 m.
        if (tolerance == 0.25f) {
            EXPECT_LT(kept.size() * 10, build.size());
        }
    }
    std::vector<glm::vec3> kink = straight;
    kink[400].x = 0.3f;
    const std::vector<std::size_t> kept = simplifiedLine(kink, 0.25f);
    EXPECT_TRUE(std::binary_search(kept.begin(), kept.end(), 400u));
}

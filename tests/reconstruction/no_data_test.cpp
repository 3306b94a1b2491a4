// Sections with too few valid arms are "no data": never drawn, classified,
// zoned or integrated (docs/analysis.md, "No data").
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/section/invalid_arm_readings.h"

#include <boost/math/constants/constants.hpp>

#include "reconstruction/analysis/report_writer.h"
#include "reconstruction/analysis/well_analysis.h"
#include "reconstruction/section/section_coverage.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_geometry.h"

using namespace caliper3d::reconstruction;
using caliper3d::io::SectionTable;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kGapTop_m = 10.0, kGapBottom_m = 12.0;  // every arm null
constexpr double kLoneRow_m = 20.0;                      // 2 of 6 arms valid: no data
constexpr double kRepairedRow_m = 5.0;                   // 4 of 6 arms valid: interpolated

// A vertical gauge well, 30 m at 0.1 m, with the rows above nulled.
SectionTable gappedWell() {
    SectionTable t = makeSyntheticWell(syntheticProfile("circle", 30.0, 0.1));
    for (std::size_t i = 0; i < t.rowCount(); ++i) {
        const double md = t.depth_m[i];
        double* r = t.radii(i);
        if (md >= kGapTop_m - 1e-6 && md <= kGapBottom_m + 1e-6)
            for (int k = 0; k < t.armCount; ++k) r[k] = kNaN;
        if (std::abs(md - kLoneRow_m) < 1e-6)
            for (int k = 0; k < 4; ++k) r[k] = kNaN;
        if (std::abs(md - kRepairedRow_m) < 1e-6) r[1] = r[4] = kNaN;
    }
    return t;
}

bool inGap(double md) {
    return (md >= kGapTop_m - 1e-6 && md <= kGapBottom_m + 1e-6) ||
           std::abs(md - kLoneRow_m) < 1e-6;
}

}  // namespace

TEST(NoDataTest, ValidArmsNeededFollowTheFractionWithAtLeastTwo) {
    EXPECT_EQ(minValidArms(6, 0.5), 3);
    EXPECT_EQ(minValidArms(4, 0.5), 2);
    EXPECT_EQ(minValidArms(3, 0.5), 2);
    EXPECT_EQ(minValidArms(2, 0.5), 2);  // one diameter needs both pads
    EXPECT_EQ(minValidArms(40, 0.5), 20);
    EXPECT_EQ(minValidArms(6, 0.0), 2);
    EXPECT_EQ(minValidArms(6, 3.0), 6);
}

TEST(NoDataTest, MeasuredSectionsCountedFromTheTableAgreeWithTheGeometry) {
    const SectionTable table = gappedWell();
    const WellGeometry g(std::make_shared<const SectionTable>(table), GeometryOptions{});
    std::size_t measured = 0;
    for (std::size_t i = 0; i < g.table().rowCount(); ++i) measured += g.measured(i);
    ASSERT_LT(measured, table.rowCount());  // the gaps hold sections without data
    const GeometryOptions options;
    EXPECT_EQ(countMeasuredSections(table, options.minValidArmFraction, options.minArmRadius_mm,
                                    options.maxArmRadius_mm),
              measured);
    // A tool reach below every reading leaves nothing measured.
    EXPECT_EQ(countMeasuredSections(table, 0.5, 0.0, 1.0), 0u);
}

TEST(NoDataTest, SectionsWithTooFewValidArmsAreNotMeasuredAndOneOrTwoMissingAre) {
    const WellGeometry g(std::make_shared<const SectionTable>(gappedWell()), GeometryOptions{});
    for (std::size_t i = 0; i < g.table().rowCount(); ++i)
        EXPECT_EQ(g.measured(i), !inGap(g.table().depth_m[i])) << g.table().depth_m[i];
    const auto gaps = g.noDataIntervals();
    ASSERT_EQ(gaps.size(), 2u);
    EXPECT_NEAR(gaps[0].top_m, kGapTop_m, 1e-6);
    EXPECT_NEAR(gaps[0].bottom_m, kGapBottom_m, 1e-6);
    EXPECT_EQ(gaps[0].sections(), 21u);
    EXPECT_NEAR(gaps[1].top_m, kLoneRow_m, 1e-6);
    EXPECT_EQ(gaps[1].sections(), 1u);
}

TEST(NoDataTest, MeshHasNoTriangleAcrossANoDataIntervalAtAnyLevel) {
    const WellGeometry g(std::make_shared<const SectionTable>(gappedWell()), GeometryOptions{});
    ASSERT_NEAR(g.path().back().tvd, g.path().back().md, 1e-9);  // vertical: depth is -y
    std::size_t trianglesSeen = 0;
    for (std::size_t s = 0; s < g.segmentCount(); ++s) {
        const SegmentMesh segment = g.buildSegment(s);
        ASSERT_EQ(segment.levels.size(), lodPyramid(g.options()).size());
        for (std::size_t level = 0; level < segment.levels.size(); ++level) {
            const Mesh& mesh = segment.levels[level];
            trianglesSeen += mesh.triangleCount();
            // Each strip joins two rings: both must lie on one side of every gap.
            double lo = 1e300, hi = -1e300;
            for (std::int32_t index : mesh.stripIndices) {
                if (index >= 0) {
                    const double depth = -mesh.positions[static_cast<std::size_t>(index)].y;
                    EXPECT_FALSE(inGap(depth) || (depth > kGapTop_m && depth < kGapBottom_m))
                        << "vertex at " << depth << " m, segment " << s << " level " << level;
                    lo = std::min(lo, depth);
                    hi = std::max(hi, depth);
                    continue;
                }
                for (double top : {kGapTop_m, kLoneRow_m})
                    EXPECT_FALSE(lo < top && hi > top)
                        << "strip " << lo << "-" << hi << " m crosses the gap at " << top
                        << " m, segment " << s << " level " << level;
                lo = 1e300;
                hi = -1e300;
            }
        }
    }
    EXPECT_GT(trianglesSeen, 0u);
}

TEST(NoDataTest, AnalysisLeavesNoDataOutOfClassesZonesAndVolumes) {
    const WellGeometry g(std::make_shared<const SectionTable>(gappedWell()), GeometryOptions{});
    const WellAnalysis a = analyseWell(g, AnalysisOptions{});
    std::size_t noData = 0;
    for (std::size_t i = 0; i < a.sections.size(); ++i) {
        const SectionResult& r = a.sections[i];
        if (inGap(r.md_m)) {
            ++noData;
            EXPECT_EQ(r.cls, BoreholeClass::NoData) << r.md_m;
            EXPECT_TRUE(std::isnan(r.dmin_mm) && std::isnan(r.dmax_mm) && std::isnan(r.area_mm2));
            EXPECT_NEAR(r.tvd_m, r.md_m, 1e-9);  // still placed on the path
        } else {
            EXPECT_EQ(r.cls, BoreholeClass::InGauge) << r.md_m;  // a gauge well
        }
    }
    EXPECT_EQ(noData, 22u);
    EXPECT_EQ(a.noDataSections, 22u);
    EXPECT_TRUE(a.zones.empty());
    EXPECT_EQ(a.repairedSections, 1u);  // the 5 m row; no-data rows are not "repaired"
    EXPECT_EQ(a.repairedArms, 2u);

    // Uncovered: from the last measured section before each gap to the first after.
    const HoleVolume& v = a.volume;
    ASSERT_EQ(v.uncovered.size(), 2u);
    EXPECT_NEAR(v.uncovered[0].first, kGapTop_m - 0.1, 1e-6);
    EXPECT_NEAR(v.uncovered[0].second, kGapBottom_m + 0.1, 1e-6);
    EXPECT_NEAR(v.uncovered[1].first, kLoneRow_m - 0.1, 1e-6);
    EXPECT_NEAR(v.uncovered[1].second, kLoneRow_m + 0.1, 1e-6);
    EXPECT_NEAR(v.uncovered_m, 2.4, 1e-6);
    // The gauge volume is the bit-size cylinder over the covered 27.6 m only.
    const double pi = boost::math::constants::pi<double>();
    const double bit_m = a.sections[0].bit_mm / 1000.0;
    EXPECT_NEAR(v.gaugeHole_m3, pi / 4.0 * bit_m * bit_m * (30.0 - 2.4), 1e-9);
    EXPECT_NEAR(v.hole_m3, v.gaugeHole_m3, 0.01 * v.gaugeHole_m3);
    const std::string summary = formatAnalysisSummary(a);
    EXPECT_NE(summary.find("not covered (no caliper data): 9.90-12.10 m, 19.90-20.10 m (2.40 m"),
              std::string::npos)
        << summary;
}

TEST(NoDataTest, ReportRowsOfNoDataHaveEmptyMeasurementsAndLasNulls) {
    const WellGeometry g(std::make_shared<const SectionTable>(gappedWell()), GeometryOptions{});
    const WellAnalysis a = analyseWell(g, AnalysisOptions{});
    std::ostringstream csv;
    writeSectionReport(csv, a);
    std::istringstream lines(csv.str());
    std::string line;
    std::getline(lines, line);
    std::size_t noDataRows = 0;
    while (std::getline(lines, line)) {
        if (line.find("no_data") == std::string::npos) continue;
        ++noDataRows;
        // md..azi present; dmin..centre offset empty; class; dls, bit; the other four empty.
        const std::size_t six = [&] {
            std::size_t p = 0;
            for (int k = 0; k < 6; ++k) p = line.find(',', p) + 1;
            return p;
        }();
        EXPECT_EQ(line.substr(six, 14), ",,,,,,no_data,") << line;
        EXPECT_EQ(line.substr(line.size() - 4), ",,,,") << line;
    }
    EXPECT_EQ(noDataRows, 22u);

    std::ostringstream las;
    writeAnalysisLas(las, a);
    // The 10.5 m row: CLASS and DMIN are the null value.
    std::istringstream in(las.str());
    bool data = false, seen = false;
    while (std::getline(in, line)) {
        if (line.rfind("~A", 0) == 0) data = true;
        if (!data || line.find("10.5000") == std::string::npos) continue;
        std::istringstream fields(line);
        std::vector<std::string> v;
        for (std::string f; fields >> f;) v.push_back(f);
        ASSERT_EQ(v.size(), 19u) << line;
        EXPECT_EQ(v[8], "-999.25");   // DMIN
        EXPECT_EQ(v[17], "-999.25");  // CLASS
        EXPECT_EQ(v[18], "-999.25");  // REPAIRED
        seen = true;
    }
    EXPECT_TRUE(seen);
}

TEST(NoDataTest, TwoPadToolWithOnePadMissingHasNoData) {
    SectionTable t = makeSyntheticWell(syntheticProfile("circle", 5.0, 0.5));
    SectionTable two;
    two.source = "two-pad";
    two.armCount = 2;
    two.depth_m = t.depth_m;
    two.bitSize_mm = t.bitSize_mm;
    for (std::size_t i = 0; i < t.rowCount(); ++i) {
        two.radius_mm.push_back(t.radii(i)[0]);
        two.radius_mm.push_back(i == 3 ? kNaN : t.radii(i)[3]);
    }
    const WellGeometry g(std::make_shared<const SectionTable>(two), GeometryOptions{});
    for (std::size_t i = 0; i < two.rowCount(); ++i) EXPECT_EQ(g.measured(i), i != 3);
}

TEST(NoDataTest, FortyFingersNeedTwentyValid) {
    SectionTable t;
    t.source = "forty";
    t.armCount = 40;
    t.depth_m = {1.0, 1.1};
    t.bitSize_mm = {215.9, 215.9};
    for (int row = 0; row < 2; ++row)
        for (int k = 0; k < 40; ++k) t.radius_mm.push_back(k < 20 - row ? 108.0 : kNaN);
    const WellGeometry g(std::make_shared<const SectionTable>(t), GeometryOptions{});
    EXPECT_TRUE(g.measured(0));   // 20 of 40
    EXPECT_FALSE(g.measured(1));  // 19 of 40
}

TEST(NoDataTest, LogWithoutAnyUsableSectionIsRejectedNamingTheFile) {
    SectionTable t = makeSyntheticWell(syntheticProfile("circle", 5.0, 0.5));
    t.source = "all-null.las";
    for (double& r : t.radius_mm) r = kNaN;
    try {
        WellGeometry g(std::make_shared<const SectionTable>(t), GeometryOptions{});
        FAIL() << "accepted a log without caliper data";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("all-null.las: no usable caliper data"),
                  std::string::npos)
            << e.what();
        // Why (every reading null) and where (the first section's depth).
        EXPECT_NE(std::string(e.what()).find(
                      "arms with a valid reading: every arm reading is null (NaN or the file's "
                      "NULL value); the first at "),
                  std::string::npos)
            << e.what();
    }
}

TEST(NoDataTest, InvalidReadingsAreCountedByKind) {
    SectionTable t;
    t.armCount = 4;
    t.depth_m = {10.0, 10.5, 11.0};
    t.radius_mm = {-5.0, -1.0,  0.0,  -3.0,   // every reading zero or negative
                   kNaN, 400.0, 90.0, kNaN,   // 1 valid of 4: no shape
                   90.0, 90.0,  90.0, 90.0};  // measured
    InvalidArmReadings counts;
    counts.add(t, 0.5, 0.0, 300.0);
    EXPECT_EQ(counts.sections, 2u);
    EXPECT_EQ(counts.readings, 8u);
    EXPECT_EQ(counts.tooSmall, 4u);
    EXPECT_EQ(counts.missing, 2u);
    EXPECT_EQ(counts.beyondReach, 1u);
    EXPECT_DOUBLE_EQ(counts.firstDepth_m, 10.0);
    EXPECT_EQ(describeInvalidArmReadings(counts, 0.0, 300.0),
              "of their 8 arm readings 2 are null (NaN or the file's NULL value), 4 are zero or "
              "negative, 1 is beyond the tool's reach of 300 mm, 1 is valid, too few in any one "
              "section");

    SectionTable negative = t;
    negative.radius_mm = {-5.0, -1.0, 0.0, -3.0, -5.0, -1.0, -2.0, -3.0, -1.0, -1.0, -1.0, -1.0};
    InvalidArmReadings all;
    all.add(negative, 0.5, 0.0, 300.0);
    EXPECT_EQ(describeInvalidArmReadings(all, 0.0, 300.0), "every arm reading is zero or negative");
    try {
        negative.source = "negative.las";
        WellGeometry g(std::make_shared<const SectionTable>(negative), GeometryOptions{});
        FAIL() << "accepted a log without caliper data";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "every arm reading is zero or negative; the first at 10.00 m"),
                  std::string::npos)
            << e.what();
    }
    SectionTable far = t;
    far.radius_mm.assign(12, 500.0);
    InvalidArmReadings reach;
    reach.add(far, 0.5, 0.0, 300.0);
    EXPECT_EQ(describeInvalidArmReadings(reach, 0.0, 300.0),
              "every arm reading is beyond the tool's reach of 300 mm");
}

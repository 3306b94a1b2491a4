// Cased hole and arms that did not open (docs/analysis.md, "Cased hole", "Arms not open"):
// constructed logs with known answers, and the real FMI log's casing from its header.
#include <algorithm>
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "io/casing_program.h"
#include "io/log_reader.h"
#include "reconstruction/analysis/report_writer.h"
#include "reconstruction/analysis/wall_colour_request.h"
#include "reconstruction/analysis/well_analysis.h"
#include "reconstruction/load/well_warnings.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "test_support.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {

using K = SyntheticFeature::Kind;

// A vertical 8.5 in hole, 100 m at 0.05 m, whose tool reads `casingReading_mm` (a circle) over
// 0-30.02 m (rows 0 to 30 m), with the features given below it.
io::SectionTable wellWith(double casingReading_mm, std::vector<SyntheticFeature> below = {}) {
    SyntheticWellSpec spec = syntheticProfile("circle", 100.0, 0.05);
    spec.features.push_back({K::Undergauge, 0.0, 30.02, casingReading_mm, casingReading_mm, 0, 0});
    for (const SyntheticFeature& f : below) spec.features.push_back(f);
    return makeSyntheticWell(spec);
}

struct Analysed {
    std::unique_ptr<WellGeometry> geometry;
    WellAnalysis analysis;
};

Analysed analyse(io::SectionTable t) {
    Analysed a;
    a.geometry = std::make_unique<WellGeometry>(
        std::make_shared<const io::SectionTable>(std::move(t)), GeometryOptions{});
    a.analysis = analyseWell(*a.geometry, AnalysisOptions{});
    return a;
}

std::size_t count(const WellAnalysis& a, BoreholeClass c, double top = -1, double bottom = 1e9) {
    return static_cast<std::size_t>(std::count_if(
        a.sections.begin(), a.sections.end(),
        [&](const SectionResult& r) { return r.cls == c && r.md_m >= top && r.md_m <= bottom; }));
}

// 8 5/8 in 32 lb/ft casing to 30.02 m: API 5CT wall 0.352 in, ID 7.921 in = 201.19 mm.
io::CasingString casing30m() {
    std::string error;
    return *io::parseCasingSpec("30.02,8.625in,32lb/ft", error);
}

}  // namespace

TEST(CasingAnalysisTest, WithoutTheCasingTheCasedIntervalIsUndergaugeAgainstTheBitBelow) {
    // What the product did before it read the casing: the issue this guards against.
    const Analysed a = analyse(wellWith(200.0));
    ASSERT_FALSE(a.analysis.zones.empty());
    EXPECT_EQ(a.analysis.zones[0].kind, BoreholeClass::Undergauge);
    EXPECT_NEAR(a.analysis.zones[0].bottom_m, 30.0, 0.1);
}

TEST(CasingAnalysisTest, CasedSectionsAreTheirOwnClassAgainstTheInnerDiameterAndLeftOutOfVolumes) {
    io::SectionTable t = wellWith(200.0);
    t.casing = {casing30m()};
    const Analysed a = analyse(std::move(t));
    const WellAnalysis& w = a.analysis;
    const std::size_t rows = w.sections.size();
    std::size_t cased = 0;
    for (const SectionResult& r : w.sections) {
        if (r.md_m <= 30.02) {
            EXPECT_EQ(r.cls, BoreholeClass::Cased) << r.md_m;
            EXPECT_NEAR(r.bit_mm, 7.921 * 25.4, 1e-9) << r.md_m;  // gauge: the casing's ID
            ++cased;
        } else {
            EXPECT_EQ(r.cls, BoreholeClass::InGauge) << r.md_m;
            EXPECT_DOUBLE_EQ(r.bit_mm, 215.9) << r.md_m;
        }
    }
    EXPECT_EQ(cased, 601u);        // 0, 0.05, ..., 30
    EXPECT_TRUE(w.zones.empty());  // no undergauge zone, and cased is not a zone
    EXPECT_EQ(w.armsNotOpen.size(), 0u);
    // Volumes: the open hole only, 30.05-99.95 m, a cylinder of the bit size.
    const double openLength = w.sections[rows - 1].md_m - 30.05;
    const double cylinder = M_PI / 4 * 0.2159 * 0.2159 * openLength;
    EXPECT_NEAR(w.volume.gaugeHole_m3, cylinder, 1e-9);
    EXPECT_NEAR(w.volume.hole_m3, cylinder, cylinder * 0.003);
    ASSERT_EQ(w.volume.cased.size(), 1u);
    EXPECT_NEAR(w.volume.cased[0].first, 0.0, 1e-12);
    EXPECT_NEAR(w.volume.cased[0].second, 30.05, 1e-9);
    EXPECT_NEAR(w.volume.cased_m, 30.05, 1e-9);
    EXPECT_TRUE(w.volume.uncovered.empty());
    // The calibration check: the tool's median reading against the nominal ID.
    ASSERT_EQ(w.casing.size(), 1u);
    const CasingCheck& c = w.casing[0];
    EXPECT_EQ(c.sections, 601u);
    EXPECT_NEAR(c.top_m, 0.0, 1e-12);
    EXPECT_NEAR(c.bottom_m, 30.0, 1e-9);
    EXPECT_NEAR(c.medianDiameter_mm, 200.0, 0.4);  // a 48-gon inscribed in the 200 mm circle
    EXPECT_DOUBLE_EQ(c.offset_mm, c.medianDiameter_mm - 7.921 * 25.4);
    EXPECT_LT(c.offset_mm, -1.19 + 0.01);
    EXPECT_GT(c.offset_mm, -1.19 - 0.4);
    const std::string summary = formatAnalysisSummary(w);
    EXPECT_NE(summary.find("cased hole left out: 0.00-30.05 m"), std::string::npos) << summary;
    EXPECT_NE(summary.find("nominal ID 201.2 mm, offset -1."), std::string::npos) << summary;
}

TEST(CasingAnalysisTest, TheWallColouredByClassShowsTheCasingInItsOwnColour) {
    io::SectionTable t = wellWith(200.0);
    t.casing = {casing30m()};
    const Analysed a = analyse(std::move(t));
    ColourRequest byClass;
    byClass.quantity = "class";
    const auto c = makeWallColouring(*a.geometry, byClass);
    ASSERT_EQ(c->legend().categories.size(), 6u);
    EXPECT_EQ(c->legend().categories[5].first, "cased");
    EXPECT_EQ(c->colour(0, 0.0), 0x4D4D4DFFu);                             // 0 m: in casing
    EXPECT_EQ(c->colour(1000, 0.0), classColour(BoreholeClass::InGauge));  // 50 m: open hole
    // Departure inside casing is from the casing's inner diameter (a gauge of 201.19 mm).
    EXPECT_NEAR(a.geometry->bitRadius_mm(0), 7.921 * 25.4 / 2.0, 1e-9);
    EXPECT_DOUBLE_EQ(a.geometry->bitRadius_mm(1000), 215.9 / 2.0);
}

TEST(CasingAnalysisTest, UnknownInnerDiameterIsCasedWithoutACheckAndSaysSo) {
    io::SectionTable t = wellWith(200.0);
    io::CasingString c;
    c.bottom_m = 30.02;
    c.size_mm = 219.075;  // no weight: ID unknown
    c.source = "test";
    t.casing = {c};
    const Analysed a = analyse(std::move(t));
    EXPECT_EQ(count(a.analysis, BoreholeClass::Cased), 601u);
    EXPECT_TRUE(std::isnan(a.analysis.sections[0].bit_mm));
    ASSERT_EQ(a.analysis.casing.size(), 1u);
    EXPECT_TRUE(std::isnan(a.analysis.casing[0].offset_mm));
    io::Diagnostics d;
    warnAnalysis(*a.geometry, a.analysis, d);
    ASSERT_EQ(d.warningCount, 1u);
    EXPECT_NE(d.warnings[0].message.find("casing to 30.02 m: nominal inner diameter unknown"),
              std::string::npos);
    EXPECT_NE(formatAnalysisSummary(a.analysis).find("nominal ID unknown: no calibration check"),
              std::string::npos);
}

TEST(CasingAnalysisTest, ArmsPinnedClosedAreNoDataNotUndergaugeButAGenuineUndergaugeStays) {
    // 110 mm in a 215.9 mm hole over 40-65 m (arms closed: 49 % under), a 3-row dip to 110 mm
    // at 90 m (too short to call), a genuine 203.9 mm undergauge over 80-85 m.
    const Analysed a = analyse(wellWith(215.9, {{K::Undergauge, 40.0, 65.0, 110.0, 110.0, 0, 0},
                                                {K::Undergauge, 80.0, 85.0, 203.9, 203.9, 0, 0},
                                                {K::Undergauge, 90.0, 90.12, 110.0, 110.0, 0, 0}}));
    const WellAnalysis& w = a.analysis;
    ASSERT_EQ(w.armsNotOpen.size(), 1u);
    EXPECT_NEAR(w.armsNotOpen[0].top_m, 40.0, 0.051);
    EXPECT_NEAR(w.armsNotOpen[0].bottom_m, 65.0, 0.051);
    EXPECT_EQ(w.armsNotOpenSections, count(w, BoreholeClass::NoData, 39.9, 65.1));
    EXPECT_GE(w.armsNotOpenSections, 500u);
    EXPECT_EQ(count(w, BoreholeClass::Undergauge, 39.9, 65.1), 0u);
    EXPECT_TRUE(std::isnan(w.sections[1000].dmax_mm));  // 50 m: no measurement reported
    EXPECT_TRUE(w.noData.empty());                      // every arm read: not the too-few-arms kind
    // The genuine undergauge and the short dip stay undergauge zones.
    std::vector<std::pair<double, double>> undergauge;
    for (const Zone& z : w.zones) {
        EXPECT_EQ(z.kind, BoreholeClass::Undergauge);
        undergauge.emplace_back(z.top_m, z.bottom_m);
    }
    ASSERT_EQ(undergauge.size(), 2u);
    EXPECT_NEAR(undergauge[0].first, 80.0, 0.06);
    EXPECT_NEAR(undergauge[0].second, 85.0, 0.06);
    EXPECT_NEAR(undergauge[1].first, 90.0, 0.06);
    // Volumes leave the closed interval out, and say so.
    ASSERT_EQ(w.volume.uncovered.size(), 1u);
    EXPECT_NEAR(w.volume.uncovered[0].first, 40.0, 0.11);
    EXPECT_NEAR(w.volume.uncovered[0].second, 65.0, 0.11);
    // Counted and shown: a warning, and the summary.
    io::Diagnostics d;
    warnAnalysis(*a.geometry, w, d);
    ASSERT_EQ(d.warningCount, 1u);
    EXPECT_NE(d.warnings[0].message.find("arms not open over 40."), std::string::npos)
        << d.warnings[0].message;
    EXPECT_NE(formatAnalysisSummary(w).find("arms not open over"), std::string::npos);
}

TEST(CasingAnalysisTest, ArmsClosedInsideCasingGiveNoCalibrationReading) {
    // Closed arms read 102 mm in a 166 mm ID casing (the FMI log's casing): no_data, and the
    // casing check has no reading rather than an offset of -64 mm.
    io::SectionTable t = wellWith(102.0);
    std::string error;
    t.casing = {*io::parseCasingSpec("30.02,7in,25.3kg/m", error)};
    const Analysed a = analyse(std::move(t));
    EXPECT_EQ(count(a.analysis, BoreholeClass::Cased), 0u);
    EXPECT_EQ(count(a.analysis, BoreholeClass::NoData, 0.0, 30.02), 601u);
    ASSERT_EQ(a.analysis.casing.size(), 1u);
    EXPECT_EQ(a.analysis.casing[0].sections, 0u);
    EXPECT_TRUE(std::isnan(a.analysis.casing[0].offset_mm));
    // Still cased hole for the volumes, not "no data".
    EXPECT_NEAR(a.analysis.volume.cased_m, 30.05, 1e-9);
    EXPECT_TRUE(a.analysis.volume.uncovered.empty());
}

TEST(CasingAnalysisTest, RealFmiCasingFromItsHeaderLeavesNoUndergaugeInside) {
    const auto file = test::sharedData() / "real" / "1AA063409108W400_FMI_SONIC_MAIN.las";
    CALIPER3D_REQUIRE_DATA(file);
    io::Diagnostics diagnostics;
    io::SectionTable table = io::readCaliperLog(file.string(), io::ReadOptions{}, &diagnostics);
    const io::LogInfo info = io::describeLog(file.string(), io::ReadOptions{});
    table.casing = info.casing;
    ASSERT_EQ(table.casing.size(), 1u);
    EXPECT_DOUBLE_EQ(table.casing[0].bottom_m, 73.2);
    const Analysed a = analyse(std::move(table));
    const WellAnalysis& w = a.analysis;
    // Inside the casing (54.71-73.2 m) the FMI's arms stay closed at 101-103 mm: no section is
    // undergauge there, and none is measured against the 251 mm bit of the BS curve.
    EXPECT_EQ(count(w, BoreholeClass::Undergauge, 0.0, 73.2), 0u);
    for (const SectionResult& r : w.sections)
        if (r.md_m <= 73.2) {
            EXPECT_TRUE(r.cls == BoreholeClass::NoData || r.cls == BoreholeClass::Cased) << r.md_m;
        }
    ASSERT_FALSE(w.armsNotOpen.empty());
    EXPECT_NEAR(w.armsNotOpen[0].top_m, 54.7116, 1e-4);
    EXPECT_GT(w.armsNotOpen[0].bottom_m, 73.2);  // the arms open below the shoe, by 73.8 m
    EXPECT_LT(w.armsNotOpen[0].bottom_m, 73.8);
    EXPECT_NEAR(w.volume.cased_m, 73.2 - 54.7116, 0.16);
}

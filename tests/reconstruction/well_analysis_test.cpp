// End to end on synthetic wells with exact known answers.
#include "reconstruction/well_analysis.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include "reconstruction/synthetic_well.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {

struct Analysed {
    SyntheticWellSpec spec;
    std::unique_ptr<WellGeometry> geometry;
    WellAnalysis analysis;
};

Analysed analyse(const std::string& profile, double length = 100.0, double step = 0.05, int arms = 6,
                 AnalysisOptions options = {}) {
    Analysed a;
    a.spec = syntheticProfile(profile, length, step);
    a.spec.armCount = arms;
    auto table = std::make_shared<const io::SectionTable>(makeSyntheticWell(a.spec));
    a.geometry = std::make_unique<WellGeometry>(table, GeometryOptions{});
    a.analysis = analyseWell(*a.geometry, options);
    return a;
}

std::size_t count(const WellAnalysis& a, BoreholeClass c, double top = -1, double bottom = 1e9) {
    return static_cast<std::size_t>(std::count_if(a.sections.begin(), a.sections.end(), [&](const SectionResult& r) {
        return r.cls == c && r.md_m >= top && r.md_m <= bottom;
    }));
}

}  // namespace

TEST(WellAnalysisTest, CircleOfBitSizeIsInGaugeEverywhere) {
    const Analysed a = analyse("circle");
    EXPECT_EQ(count(a.analysis, BoreholeClass::InGauge), a.analysis.sections.size());
    for (const SectionResult& r : a.analysis.sections) {
        EXPECT_NEAR(r.dmax_mm, 215.9, 1e-6);
        EXPECT_NEAR(r.equivalentDiameter_mm, 215.9, 0.4);  // 48-gon inscribed in the circle
    }
    EXPECT_TRUE(a.analysis.zones.empty());
    EXPECT_EQ(a.analysis.breakouts.quality, 'E');
    EXPECT_EQ(a.analysis.repairedSections, 0u);
}

TEST(WellAnalysisTest, EllipseGivesItsAxesAndWorldAzimuthWhateverTheToolRotation) {
    // Six pads: the spline through them is close to, not exactly, the ellipse.
    const Analysed six = analyse("ellipse");
    const Analysed many = analyse("ellipse", 100.0, 0.05, 24);
    for (const auto* a : {&six, &many}) {
        const double tol = a == &six ? 2.0 : 0.2;
        for (std::size_t i = 0; i < a->analysis.sections.size(); i += 97) {
            const SectionResult& r = a->analysis.sections[i];
            EXPECT_NEAR(r.dmax_mm, 245.9, tol) << r.md_m;
            EXPECT_NEAR(r.dmin_mm, 217.9, tol) << r.md_m;
            EXPECT_NEAR(r.majorAzimuth_deg, 60.0, a == &six ? 1.5 : 0.2) << r.md_m;
            EXPECT_EQ(r.cls, BoreholeClass::Breakout) << r.md_m;
        }
        ASSERT_EQ(a->analysis.zones.size(), 1u);
        EXPECT_NEAR(a->analysis.zones[0].meanAzimuth_deg, 60.0, 1.0);
        EXPECT_EQ(a->analysis.breakouts.zoneCount, 1);
        EXPECT_EQ(a->analysis.breakouts.quality, 'D');  // one zone: D at best
    }
}

TEST(WellAnalysisTest, WashoutAndUndergaugeZonesSitWhereTheyWereMade) {
    const Analysed w = analyse("washout");
    ASSERT_EQ(w.analysis.zones.size(), 1u);
    EXPECT_EQ(w.analysis.zones[0].kind, BoreholeClass::Washout);
    EXPECT_NEAR(w.analysis.zones[0].top_m, 40.0, 0.05);
    EXPECT_NEAR(w.analysis.zones[0].bottom_m, 60.0, 0.05);
    const Analysed u = analyse("undergauge");
    ASSERT_EQ(u.analysis.zones.size(), 1u);
    EXPECT_EQ(u.analysis.zones[0].kind, BoreholeClass::Undergauge);
    EXPECT_NEAR(u.analysis.zones[0].length_m, 20.0, 0.1);
}

TEST(WellAnalysisTest, KeyseatOnTheHighSideOfABuildIsNotABreakout) {
    const Analysed k = analyse("keyseat", 300.0, 0.1);
    EXPECT_EQ(count(k.analysis, BoreholeClass::Breakout), 0u);
    const std::size_t inFeature = count(k.analysis, BoreholeClass::Keyseat, 180.0, 240.0);
    EXPECT_GT(inFeature, 590u);  // every section of 180-240 m
    for (const SectionResult& r : k.analysis.sections) {
        if (r.md_m < 181.0 || r.md_m > 239.0) continue;
        EXPECT_NEAR(std::min(r.majorFromHighSide_deg, 180.0 - r.majorFromHighSide_deg), 0.0, 3.0);  // six pads
        EXPECT_GT(r.centreOffset_mm, 8.0);  // asymmetric: the centre moves towards the groove
    }
}

TEST(WellAnalysisTest, OffCentreToolReportsTheHoleCentreOffsetAndItsAzimuth) {
    const Analysed o = analyse("offcentre", 50.0, 0.5, 24);
    for (const SectionResult& r : o.analysis.sections) {
        EXPECT_NEAR(r.centreOffset_mm, 15.0, 0.2);
        EXPECT_NEAR(r.centreOffsetAzimuth_deg, 90.0, 0.5);
        EXPECT_NEAR(r.dmax_mm, 215.9, 0.5);
        EXPECT_EQ(r.cls, BoreholeClass::InGauge);
    }
}

TEST(WellAnalysisTest, StuckArmIsInterpolatedCountedAndLeavesNoSpike) {
    const Analysed s = analyse("stuck-arm");
    EXPECT_EQ(s.analysis.repairedSections, 401u);  // 40.00-60.00 m at 0.05 m
    EXPECT_EQ(s.analysis.repairedArms, 401u);
    for (const SectionResult& r : s.analysis.sections) {
        EXPECT_NEAR(r.dmin_mm, 215.9, 1e-6);
        EXPECT_EQ(r.cls, BoreholeClass::InGauge);
    }
    // An arm beyond the tool's reach is missing too.
    auto spec = syntheticProfile("stuck-arm", 100.0, 0.05);
    spec.stuckValue_mm = 900.0;
    GeometryOptions g;
    g.maxArmRadius_mm = 250.0;
    WellGeometry geometry(std::make_shared<const io::SectionTable>(makeSyntheticWell(spec)), g);
    EXPECT_EQ(analyseWell(geometry, {}).repairedSections, 401u);
}

TEST(WellAnalysisTest, ExampleWellHasItsBreakoutWashoutAndBuild) {
    const Analysed e = analyse("example", 300.0, 0.05);
    std::vector<BoreholeClass> kinds;
    for (const Zone& z : e.analysis.zones) kinds.push_back(z.kind);
    ASSERT_EQ(kinds.size(), 2u);
    EXPECT_EQ(kinds[0], BoreholeClass::Breakout);
    EXPECT_NEAR(e.analysis.zones[0].top_m, 60.0, 0.05);
    EXPECT_NEAR(e.analysis.zones[0].meanAzimuth_deg, 135.0, 1.5);
    EXPECT_EQ(kinds[1], BoreholeClass::Washout);
    EXPECT_NEAR(e.analysis.sections.back().inc_deg, 15.0, 1e-9);
}

TEST(WellAnalysisTest, TwoThreadsGiveTheSameAnswerAsOne) {
    AnalysisOptions two;
    two.threads = 2;
    const Analysed a = analyse("example", 300.0, 0.05);
    const Analysed b = analyse("example", 300.0, 0.05, 6, two);
    ASSERT_EQ(a.analysis.sections.size(), b.analysis.sections.size());
    for (std::size_t i = 0; i < a.analysis.sections.size(); ++i) {
        EXPECT_EQ(a.analysis.sections[i].dmax_mm, b.analysis.sections[i].dmax_mm);
        EXPECT_EQ(a.analysis.sections[i].cls, b.analysis.sections[i].cls);
    }
}

TEST(WellAnalysisTest, BitSizeOptionOverridesTheLog) {
    AnalysisOptions o;
    o.bitSize_mm = 190.0;  // the gauge hole is now a washout
    const Analysed a = analyse("circle", 20.0, 0.1, 6, o);
    EXPECT_EQ(count(a.analysis, BoreholeClass::Washout), a.analysis.sections.size());
}

TEST(WellAnalysisTest, VolumesOfAGaugeHoleMatchTheCylinder) {
    AnalysisOptions o;
    o.volume.casingOd_mm = 177.8;
    const Analysed a = analyse("circle", 100.0, 0.05, 24, o);
    const double cylinder = M_PI / 4 * 0.2159 * 0.2159 * 100.0;
    EXPECT_NEAR(a.analysis.volume.gaugeHole_m3, cylinder, 1e-9);
    EXPECT_NEAR(a.analysis.volume.hole_m3, cylinder, cylinder * 0.003);  // inscribed 48-gon
    EXPECT_NEAR(a.analysis.volume.gaugeAnnulus_m3, cylinder - M_PI / 4 * 0.1778 * 0.1778 * 100.0, 1e-9);
}

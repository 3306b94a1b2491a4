// End to end on synthetic wells with exact known answers.
#include "reconstruction/analysis/well_analysis.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <cstring>

#include <gtest/gtest.h>

#include <glm/trigonometric.hpp>

#include "reconstruction/section/section_analysis.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "support/reconstruction_support.h"
#include "test_support.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {

struct Analysed {
    SyntheticWellSpec spec;
    std::unique_ptr<WellGeometry> geometry;
    WellAnalysis analysis;
};

Analysed analyse(const std::string& profile, double length = 100.0, double step = 0.05,
                 int arms = 6, AnalysisOptions options = {}) {
    Analysed a;
    a.spec = syntheticProfile(profile, length, step);
    a.spec.armCount = arms;
    auto table = std::make_shared<const io::SectionTable>(makeSyntheticWell(a.spec));
    a.geometry = std::make_unique<WellGeometry>(table, GeometryOptions{});
    a.analysis = analyseWell(*a.geometry, options);
    return a;
}

std::size_t count(const WellAnalysis& a, BoreholeClass c, double top = -1, double bottom = 1e9) {
    return static_cast<std::size_t>(std::count_if(
        a.sections.begin(), a.sections.end(),
        [&](const SectionResult& r) { return r.cls == c && r.md_m >= top && r.md_m <= bottom; }));
}

}  // namespace

TEST(WellAnalysisTest, CircleOfBitSizeIsInGaugeEverywhere) {
    const Analysed a = analyse("circle");
    EXPECT_EQ(count(a.analysis, BoreholeClass::InGauge), a.analysis.sections.size());
    for (const SectionResult& r : a.analysis.sections) {
        EXPECT_NEAR(r.dmax_mm, 215.9, test::storedInFloat(215.9));
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
    // Round sections (a circle everywhere): no major axis, so the zone has no
    // mean azimuth either, and a centred tool no offset direction.
    EXPECT_TRUE(std::isnan(w.analysis.zones[0].meanAzimuth_deg));
    for (const SectionResult& r : w.analysis.sections) {
        EXPECT_TRUE(std::isnan(r.majorAzimuth_deg)) << r.md_m;
        EXPECT_TRUE(std::isnan(r.majorFromHighSide_deg)) << r.md_m;
        EXPECT_TRUE(std::isnan(r.centreOffsetAzimuth_deg)) << r.md_m;
    }
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
        EXPECT_NEAR(std::min(r.majorFromHighSide_deg, 180.0 - r.majorFromHighSide_deg), 0.0,
                    3.0);                   // six pads
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
    // Six pads of the same round hole: the spline adds 0.13 mm of elongation whose
    // axis turns with the tool; below axis_min_elongation_mm there is no axis to report.
    const Analysed six = analyse("offcentre", 50.0, 0.5, 6);
    for (const SectionResult& r : six.analysis.sections) {
        EXPECT_LT(r.dmax_mm - r.dmin_mm, 0.5);
        EXPECT_TRUE(std::isnan(r.majorAzimuth_deg)) << r.md_m;
        EXPECT_NEAR(r.centreOffset_mm, 15.0, 0.2);
        EXPECT_NEAR(r.centreOffsetAzimuth_deg, 90.0, 0.5);
    }
}

TEST(WellAnalysisTest, StuckArmIsInterpolatedCountedAndLeavesNoSpike) {
    const Analysed s = analyse("stuck-arm");
    EXPECT_EQ(s.analysis.repairedSections, 401u);  // 40.00-60.00 m at 0.05 m
    EXPECT_EQ(s.analysis.repairedArms, 401u);
    for (const SectionResult& r : s.analysis.sections) {
        EXPECT_NEAR(r.dmin_mm, 215.9, test::storedInFloat(215.9));
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
    EXPECT_NEAR(a.analysis.volume.gaugeAnnulus_m3, cylinder - M_PI / 4 * 0.1778 * 0.1778 * 100.0,
                1e-9);
}

namespace {

// A well of several analysis blocks with every feature: breakout, washout,
// key seat, undergauge, stuck and missing arms, null orientation readings.
std::shared_ptr<const io::SectionTable> featureWell() {
    auto spec = syntheticProfile("example", 60.0, 0.005);
    using K = SyntheticFeature::Kind;
    spec.features.push_back({K::Keyseat, 40.0, 45.0, 240.9, 215.9, 0.0, 12.5});
    spec.features.push_back({K::Undergauge, 50.0, 52.0, 203.9, 203.9, 0.0, 0.0});
    spec.kickoff_m = 10.0;
    spec.buildRate_degPer30m = 12.0;
    spec.stuckArm = 2;
    spec.stuckTop_m = 20.0;
    spec.stuckBottom_m = 21.0;
    io::SectionTable t = makeSyntheticWell(spec);
    for (std::size_t i = 0; i < t.rowCount(); i += 101) t.radii(i)[i % 6] = std::nan("");
    for (std::size_t i = 3000; i < 3100; ++i) t.p1az_deg[i] = std::nan("");
    for (std::size_t i = 3050; i < 3150; ++i) t.rb_deg[i] = std::nan("");
    return std::make_shared<const io::SectionTable>(std::move(t));
}

bool same(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// `computed` as the analysis stores it (SectionMeasure: single precision).
double stored(double computed) {
    return static_cast<float>(computed);
}

}  // namespace

TEST(WellAnalysisTest, AnyNumberOfThreadsGivesTheSameResultsBitForBit) {
    const auto table = featureWell();
    const WellGeometry g(table, GeometryOptions{});
    const WellAnalysis one = analyseWell(g, {});
    ASSERT_GT(one.sections.size(), 2 * 4096u);  // three blocks
    for (int threads : {2, 3}) {
        AnalysisOptions options;
        options.threads = threads;
        const WellAnalysis many = analyseWell(g, options);
        ASSERT_EQ(many.sections.size(), one.sections.size());
        std::size_t differ = 0;
        for (std::size_t i = 0; i < one.sections.size(); ++i) {
            const SectionResult &a = one.sections[i], &b = many.sections[i];
            const double fa[] = {a.md_m,
                                 a.tvd_m,
                                 a.north_m,
                                 a.east_m,
                                 a.inc_deg,
                                 a.azi_deg,
                                 a.dls_degPer30m,
                                 a.bit_mm,
                                 a.area_mm2,
                                 a.equivalentDiameter_mm,
                                 a.dmin_mm,
                                 a.dmax_mm,
                                 a.ellipticity,
                                 a.majorAzimuth_deg,
                                 a.majorFromHighSide_deg,
                                 a.centreOffset_mm,
                                 a.centreOffsetAzimuth_deg};
            const double fb[] = {b.md_m,
                                 b.tvd_m,
                                 b.north_m,
                                 b.east_m,
                                 b.inc_deg,
                                 b.azi_deg,
                                 b.dls_degPer30m,
                                 b.bit_mm,
                                 b.area_mm2,
                                 b.equivalentDiameter_mm,
                                 b.dmin_mm,
                                 b.dmax_mm,
                                 b.ellipticity,
                                 b.majorAzimuth_deg,
                                 b.majorFromHighSide_deg,
                                 b.centreOffset_mm,
                                 b.centreOffsetAzimuth_deg};
            for (int k = 0; k < 17; ++k) differ += same(fa[k], fb[k]) ? 0 : 1;
            differ += a.repairedArms != b.repairedArms || a.cls != b.cls;
        }
        EXPECT_EQ(differ, 0u) << threads << " threads";
        ASSERT_EQ(many.zones.size(), one.zones.size());
        for (std::size_t z = 0; z < one.zones.size(); ++z) {
            EXPECT_EQ(many.zones[z].firstSection, one.zones[z].firstSection);
            EXPECT_EQ(many.zones[z].lastSection, one.zones[z].lastSection);
            EXPECT_TRUE(same(many.zones[z].meanAzimuth_deg, one.zones[z].meanAzimuth_deg));
            EXPECT_TRUE(same(many.zones[z].circularSd_deg, one.zones[z].circularSd_deg));
        }
        EXPECT_TRUE(same(many.volume.hole_m3, one.volume.hole_m3));
        EXPECT_TRUE(same(many.volume.gaugeHole_m3, one.volume.gaugeHole_m3));
        EXPECT_TRUE(same(many.padAzimuthOffset.mean_deg, one.padAzimuthOffset.mean_deg));
        EXPECT_TRUE(same(many.padAzimuthOffset.sd_deg, one.padAzimuthOffset.sd_deg));
        EXPECT_EQ(many.repairedSections, one.repairedSections);
        EXPECT_EQ(many.repairedArms, one.repairedArms);
        EXPECT_EQ(many.unorientedSections, one.unorientedSections);
    }
}

TEST(WellAnalysisTest, ResultsAreTheOneSectionFunctionsResults) {
    // Shape values bit for bit, as stored (single precision); world angles (dot products on
    // the frame rather than angle round trips) to a float's step at 180 deg; classes, zones, volume
    // and the P1AZ check exactly as the public functions give them from those values.
    const auto table = featureWell();
    const WellGeometry g(table, GeometryOptions{});
    AnalysisOptions options;
    options.threads = 2;
    options.volume.casingOd_mm = 177.8;
    const WellAnalysis a = analyseWell(g, options);
    const SectionAnalyzer analyzer(table->armCount, 48);
    std::vector<double> pads(static_cast<std::size_t>(table->armCount)), sampled(48);
    std::vector<ClassifierInput> in;
    std::vector<double> md, azimuth, dmax, dmin, area, bit;
    std::size_t differ = 0;
    auto axisDistance = [](double x, double y) {
        const double d = std::fmod(std::abs(x - y), 180.0);
        return std::min(d, 180.0 - d);
    };
    for (std::size_t i = 0; i < a.sections.size(); ++i) {
        const SectionResult& r = a.sections[i];
        EXPECT_EQ(r.repairedArms, g.repairRadii(i, pads.data()));
        const SectionShape s = analyzer.analyse(pads.data(), sampled.data());
        differ += !same(r.area_mm2, stored(s.area_mm2)) ||
                  !same(r.equivalentDiameter_mm, stored(s.equivalentDiameter_mm)) ||
                  !same(r.dmin_mm, stored(s.dmin_mm)) || !same(r.dmax_mm, stored(s.dmax_mm)) ||
                  !same(r.ellipticity, stored(s.ellipticity)) ||
                  !same(r.centreOffset_mm, stored(s.centreOffset_mm));
        const SectionFrame& f = g.frame(i);
        const PathPoint& p = g.path()[i];
        // Round: no major axis; centred (to a hundredth of a millimetre): no offset direction.
        // No P1AZ nor RB on the row: no angle of the shape is known.
        const bool unoriented = g.orientation(i) == WellGeometry::Orientation::Unoriented;
        if (unoriented) {
            EXPECT_TRUE(std::isnan(r.majorAzimuth_deg)) << i;
            EXPECT_TRUE(std::isnan(r.majorFromHighSide_deg)) << i;
            EXPECT_TRUE(std::isnan(r.centreOffsetAzimuth_deg)) << i;
        } else if (s.dmax_mm - s.dmin_mm < options.rules.axisMinElongation_mm) {
            EXPECT_TRUE(std::isnan(r.majorAzimuth_deg)) << i;
            EXPECT_TRUE(std::isnan(r.majorFromHighSide_deg)) << i;
        } else {
            EXPECT_LT(axisDistance(r.majorAzimuth_deg, inPlaneAzimuth_deg(f, s.majorAngle_deg)),
                      test::storedInFloat(180.0))
                << i;
            EXPECT_LT(
                axisDistance(r.majorFromHighSide_deg,
                             angleFromHighSide_deg(f, p.inc_deg, p.azi_deg, s.majorAngle_deg)),
                test::storedInFloat(180.0))
                << i;
            EXPECT_GE(r.majorFromHighSide_deg, 0.0);
            EXPECT_LT(r.majorFromHighSide_deg, 180.0);
        }
        if (s.centreOffset_mm >= 0.01 && !unoriented) {
            const double expected =
                inPlaneAzimuth_deg(f, glm::degrees(std::atan2(s.centroidV_mm, s.centroidU_mm)));
            const double d = std::abs(r.centreOffsetAzimuth_deg - expected);
            EXPECT_LT(std::min(d, 360.0 - d), test::storedInFloat(360.0)) << i;
        } else {
            EXPECT_TRUE(std::isnan(r.centreOffsetAzimuth_deg)) << i;
        }
        const double p1az = table->p1az_deg[i];
        in.push_back({r.md_m, r.dmin_mm, r.dmax_mm, r.bit_mm, r.inc_deg, r.majorFromHighSide_deg,
                      std::isfinite(p1az) ? p1az : table->rb_deg[i]});
        md.push_back(r.md_m);
        azimuth.push_back(r.majorAzimuth_deg);
        dmax.push_back(r.dmax_mm);
        dmin.push_back(r.dmin_mm);
        area.push_back(r.area_mm2);
        bit.push_back(r.bit_mm);
    }
    EXPECT_EQ(differ, 0u);
    const std::vector<BoreholeClass> classes = classifySections(in, options.rules);
    std::size_t classDiffer = 0;
    for (std::size_t i = 0; i < classes.size(); ++i) classDiffer += classes[i] != a.sections[i].cls;
    EXPECT_EQ(classDiffer, 0u);
    std::vector<BoreholeClass> kinds;
    for (const Zone& z : a.zones) kinds.push_back(z.kind);
    EXPECT_NE(std::find(kinds.begin(), kinds.end(), BoreholeClass::Keyseat), kinds.end());
    EXPECT_NE(std::find(kinds.begin(), kinds.end(), BoreholeClass::Undergauge), kinds.end());
    const std::vector<Zone> zones = detectZones(md, classes, azimuth, dmax, dmin);
    ASSERT_EQ(a.zones.size(), zones.size());
    for (std::size_t z = 0; z < zones.size(); ++z) {
        EXPECT_EQ(a.zones[z].kind, zones[z].kind);
        EXPECT_EQ(a.zones[z].firstSection, zones[z].firstSection);
        EXPECT_EQ(a.zones[z].lastSection, zones[z].lastSection);
        EXPECT_TRUE(same(a.zones[z].length_m, zones[z].length_m));
        EXPECT_TRUE(same(a.zones[z].meanAzimuth_deg, zones[z].meanAzimuth_deg));
        EXPECT_TRUE(same(a.zones[z].meanDmax_mm, zones[z].meanDmax_mm));
    }
    const HoleVolume v = holeVolume(md, area, bit, options.volume);
    EXPECT_TRUE(same(a.volume.hole_m3, v.hole_m3));
    EXPECT_TRUE(same(a.volume.gaugeHole_m3, v.gaugeHole_m3));
    EXPECT_TRUE(same(a.volume.annulus_m3, v.annulus_m3));
    EXPECT_TRUE(same(a.volume.cement_m3, v.cement_m3));
    const OrientationOffset o = padAzimuthOffset(*table);
    EXPECT_GT(o.samples, 1000u);
    EXPECT_EQ(a.padAzimuthOffset.samples, o.samples);
    EXPECT_TRUE(same(a.padAzimuthOffset.mean_deg, o.mean_deg));
    EXPECT_TRUE(same(a.padAzimuthOffset.sd_deg, o.sd_deg));
}

TEST(WellAnalysisTest, WithoutAnyBitSizeTheMedianDiameterIsTheGaugeOnEveryThreadCount) {
    io::SectionTable t = *featureWell();
    t.bitSize_mm.clear();
    const WellGeometry g(std::make_shared<const io::SectionTable>(std::move(t)), GeometryOptions{});
    AnalysisOptions two;
    two.threads = 2;
    const WellAnalysis a = analyseWell(g, {}), b = analyseWell(g, two);
    EXPECT_TRUE(a.bitSizeFromSections);
    EXPECT_NEAR(a.sections.front().bit_mm, 215.9, 0.5);
    EXPECT_GT(a.volume.gaugeHole_m3, 0.0);
    ASSERT_EQ(a.zones.size(), b.zones.size());
    for (std::size_t i = 0; i < a.sections.size(); ++i) {
        ASSERT_EQ(a.sections[i].cls, b.sections[i].cls);
        ASSERT_EQ(a.sections[i].bit_mm, b.sections[i].bit_mm);
    }
    EXPECT_TRUE(same(a.volume.gaugeHole_m3, b.volume.gaugeHole_m3));
}

namespace {
// A vertical two-pad log: pad 1 at 110 mm, pad 2 at 90 mm, pad 1 towards azimuth 30.
std::shared_ptr<const io::SectionTable> twoPadLog(double bit_mm) {
    io::SectionTable t;
    t.armCount = 2;
    for (int i = 0; i < 41; ++i) {
        t.depth_m.push_back(100.0 + 0.5 * i);
        t.radius_mm.push_back(110.0);
        t.radius_mm.push_back(90.0);
        t.p1az_deg.push_back(30.0);
        t.devi_deg.push_back(0.0);
        t.hazi_deg.push_back(0.0);
        t.bitSize_mm.push_back(bit_mm);
    }
    return std::make_shared<const io::SectionTable>(std::move(t));
}
}  // namespace

TEST(WellAnalysisTest, TwoPadsAreTheCircleThroughBothCentredHalfWay) {
    // One diameter of 200 mm, the tool 10 mm off its middle towards pad 1.
    const WellGeometry g(twoPadLog(200.0), GeometryOptions{});
    ASSERT_EQ(g.knotCount(), kTwoPadKnots);
    std::vector<double> knots(kTwoPadKnots);
    g.sectionKnots(0, knots.data());
    EXPECT_DOUBLE_EQ(knots[0], 110.0);  // pad 1
    EXPECT_DOUBLE_EQ(knots[4], 90.0);   // pad 2, 180 deg on
    // 90 deg on: the circle of radius 100 centred 10 mm out, seen from the tool: sqrt(100^2 -
    // 10^2).
    EXPECT_NEAR(knots[2], std::sqrt(100.0 * 100.0 - 10.0 * 10.0), 1e-9);
    const WellAnalysis a = analyseWell(g, AnalysisOptions{});
    // The 48-gon inscribed in a 200 mm circle: 200 sqrt(48/(2 pi) sin(2 pi/48)) = 199.715 mm.
    const double polygon = 200.0 * std::sqrt(48.0 / (2.0 * M_PI) * std::sin(2.0 * M_PI / 48.0));
    for (const SectionResult& r : a.sections) {
        EXPECT_NEAR(r.equivalentDiameter_mm, polygon, 0.05) << r.md_m;
        EXPECT_NEAR(r.dmax_mm, 200.0, 1e-9) << r.md_m;  // the diameter measured: r1 + r2
        EXPECT_NEAR(r.dmin_mm, 200.0, 1e-9) << r.md_m;
        EXPECT_EQ(r.ellipticity, 1.0) << r.md_m;
        EXPECT_NEAR(r.centreOffset_mm, 10.0, 1e-9) << r.md_m;  // (r1 - r2) / 2 towards pad 1
        EXPECT_NEAR(r.centreOffsetAzimuth_deg, 30.0, 0.01) << r.md_m;
        EXPECT_TRUE(std::isnan(r.majorAzimuth_deg)) << r.md_m;  // a circle has no major axis
        EXPECT_EQ(r.cls, BoreholeClass::InGauge) << r.md_m;
    }
    // The same hole drilled with a 7 in (177.8 mm) bit: 200 > 177.8 + 12.7, a washout.
    const WellGeometry small(twoPadLog(177.8), GeometryOptions{});
    const WellAnalysis w = analyseWell(small, AnalysisOptions{});
    ASSERT_EQ(w.zones.size(), 1u);
    EXPECT_EQ(w.zones[0].kind, BoreholeClass::Washout);
    // Two pads can never show a breakout or keyseat: their section is round.
    EXPECT_EQ(count(w, BoreholeClass::Breakout) + count(w, BoreholeClass::Keyseat), 0u);
}

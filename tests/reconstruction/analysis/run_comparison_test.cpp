// Two runs of one synthetic well, each with a known difference: a deeper counter, a wider
// breakout, a new washout, a tool that sits 90 degrees round, arms that did not open, casing
// read with a bias.
#include "reconstruction/analysis/run_comparison.h"

#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "reconstruction/analysis/comparison_writer.h"
#include "reconstruction/synthetic/synthetic_well.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {

using Kind = SyntheticFeature::Kind;

constexpr double kBit = 215.9;
// The equivalent diameter of a 48-gon inscribed in a circle of diameter d is d times this.
const double kInscribed = std::sqrt(24.0 * std::sin(2.0 * M_PI / 48.0) / M_PI);

struct AnalysedRun {
    std::shared_ptr<const io::SectionTable> table;
    std::unique_ptr<WellGeometry> geometry;
    WellAnalysis analysis;
    ComparedRun compared() const { return {geometry.get(), &analysis}; }
};

AnalysedRun analyse(io::SectionTable table) {
    AnalysedRun r;
    r.table = std::make_shared<const io::SectionTable>(std::move(table));
    r.geometry = std::make_unique<WellGeometry>(r.table, GeometryOptions{});
    r.analysis = analyseWell(*r.geometry, AnalysisOptions{});
    return r;
}

// The first run: a vertical 150 m hole sampled every 5 cm, a breakout 245.9 x 217.9 mm at
// azimuth 135 over 40-45 m, a gamma-ray log.
SyntheticWellSpec firstRun(int arms = 6) {
    SyntheticWellSpec spec;
    spec.length_m = 150.0;
    spec.step_m = 0.05;
    spec.armCount = arms;
    spec.gammaRay = true;
    spec.features.push_back({Kind::Breakout, 40.0, 45.0, 245.9, 217.9, 135.0, 0.0});
    return spec;
}

DepthCurve gammaOf(const io::SectionTable& t) {
    return {t.depth_m, t.extraCurves.at(0).values};
}

RunComparison compare(const AnalysedRun& a, const AnalysedRun& b,
                      double limit = kImagerRepeatability95_mm, double outlineGate = 0.0) {
    RunComparisonOptions options;
    options.outlineGate = outlineGate;
    options.mapping = fitDepthMapping(gammaOf(*a.table), gammaOf(*b.table));
    options.mapping.curve = "GR";
    options.repeatability95_mm = limit;
    return compareRuns(a.compared(), b.compared(), options);
}

bool inside(double md, double top, double bottom, double margin) {
    return md > top + margin && md < bottom - margin;
}

}  // namespace

TEST(RunComparisonTest, DeeperCounterWiderBreakoutAndNewWashoutAreFoundAtTheirDepths) {
    // Run 2: the counter reads 0.35 m deeper, the breakout is 10 mm wider (255.9 mm) over its
    // 5 m, and a 2 m washout (265.9 mm round) is new at 100-102 m. A 24-arm tool, whose spline
    // follows the ellipse to well under 0.5 mm (six pads: the next test).
    const AnalysedRun run1 = analyse(makeSyntheticWell(firstRun(24)));
    SyntheticWellSpec spec2 = firstRun(24);
    spec2.depthOffset_m = 0.35;
    spec2.features[0].dmax_mm = 255.9;
    spec2.features.push_back({Kind::Washout, 100.0, 102.0, 265.9, 265.9, 0.0, 0.0});
    const AnalysedRun run2 = analyse(makeSyntheticWell(spec2));
    const RunComparison r = compare(run1, run2);

    EXPECT_NEAR(r.mapping.shift_m, 0.35, 0.01);
    EXPECT_GT(r.mapping.match.correlation, 0.99);
    const double deqChange = kInscribed * (std::sqrt(255.9 * 217.9) - std::sqrt(245.9 * 217.9));
    for (const SectionChange& c : r.sections) {
        ASSERT_TRUE(c.compared()) << c.md1_m;
        EXPECT_NEAR(c.md2_m, c.md1_m + 0.35, 0.01);
        if (inside(c.md1_m, 40.0, 45.0, 0.1)) {
            EXPECT_NEAR(c.dmax2_mm - c.dmax1_mm, 10.0, 0.5) << c.md1_m;
            EXPECT_NEAR(c.dmin2_mm - c.dmin1_mm, 0.0, 0.5) << c.md1_m;
            EXPECT_NEAR(c.deq2_mm - c.deq1_mm, deqChange, 0.5) << c.md1_m;
            EXPECT_TRUE(c.significant) << c.md1_m;
            // The wall moved out 5 mm at the ends of the major axis (135 or 315 deg).
            EXPECT_NEAR(c.maxGrowth_mm, 5.0, 0.5) << c.md1_m;
            EXPECT_NEAR(std::fmod(c.maxGrowthAzimuth_deg, 180.0), 135.0, 7.5) << c.md1_m;
        } else if (inside(c.md1_m, 100.0, 102.0, 0.1)) {
            EXPECT_NEAR(c.deq2_mm - c.deq1_mm, kInscribed * 50.0, 0.5) << c.md1_m;
            EXPECT_NEAR(c.dmin2_mm - c.dmin1_mm, 50.0, 0.5) << c.md1_m;
            EXPECT_EQ(c.class2, BoreholeClass::Washout);
            // Widened alike all round: a growth of 25 mm with no azimuth.
            EXPECT_NEAR(c.maxGrowth_mm, 25.0, 0.5) << c.md1_m;
            EXPECT_TRUE(std::isnan(c.maxGrowthAzimuth_deg)) << c.md1_m;
        } else if (!inside(c.md1_m, 39.5, 45.5, -0.6) && !inside(c.md1_m, 99.5, 102.5, -0.6)) {
            EXPECT_NEAR(c.deq2_mm - c.deq1_mm, 0.0, 0.5) << c.md1_m;
            EXPECT_NEAR(c.dmax2_mm - c.dmax1_mm, 0.0, 0.5) << c.md1_m;
            EXPECT_FALSE(c.significant) << c.md1_m;
        }
    }
    ASSERT_EQ(r.zones.size(), 2u);
    EXPECT_EQ(r.zones[0].kind, ZoneChange::Kind::Grew);
    EXPECT_EQ(r.zones[0].cls, BoreholeClass::Breakout);
    EXPECT_NEAR(r.zones[0].maxDmaxChange_mm, 10.0, 0.5);
    EXPECT_EQ(r.zones[1].kind, ZoneChange::Kind::Appeared);
    EXPECT_EQ(r.zones[1].cls, BoreholeClass::Washout);
    EXPECT_NEAR(r.zones[1].top1_m, 100.0, 0.06);
    EXPECT_NEAR(r.zones[1].bottom1_m, 102.0, 0.06);
    EXPECT_NEAR(r.zones[1].top2_m, 100.35, 0.06);
    EXPECT_NEAR(r.zones[1].bottom2_m, 102.35, 0.06);
    EXPECT_FALSE(r.agree());
    // Volume: the washout adds pi/4 (265.9^2 - 215.9^2) mm2 over 2 m, the breakout
    // pi/4 (255.9 - 245.9) 217.9 mm2 over 5 m (each times the 48-gon's area ratio).
    const double added = M_PI / 4.0 * kInscribed * kInscribed *
                         ((265.9 * 265.9 - kBit * kBit) * 2.0 + 10.0 * 217.9 * 5.0) * 1e-6;
    EXPECT_NEAR(r.volume2_m3 - r.volume1_m3, added, 0.05 * added);
    EXPECT_NE(formatComparisonSummary(r).find("washout 99.98-101.98 m appeared"), std::string::npos)
        << formatComparisonSummary(r);
    EXPECT_EQ(formatComparisonSummary(r).find("weak"), std::string::npos);
}

TEST(RunComparisonTest, SixPadsSeeTheWiderBreakoutWithinTheirSplineError) {
    // The same pair with six pads: the closed spline through six points of an ellipse departs
    // from it by up to ~2 mm as the tool turns, differently for a wider ellipse, so a 10 mm
    // wider breakout reads 8.5-11.5 mm wider; still far beyond the 3 mm limit.
    const AnalysedRun run1 = analyse(makeSyntheticWell(firstRun(6)));
    SyntheticWellSpec spec2 = firstRun(6);
    spec2.depthOffset_m = 0.35;
    spec2.features[0].dmax_mm = 255.9;
    const AnalysedRun run2 = analyse(makeSyntheticWell(spec2));
    const RunComparison r = compare(run1, run2);
    EXPECT_NEAR(r.mapping.shift_m, 0.35, 0.01);
    for (const SectionChange& c : r.sections)
        if (inside(c.md1_m, 40.0, 45.0, 0.1)) {
            EXPECT_NEAR(c.dmax2_mm - c.dmax1_mm, 10.0, 1.5) << c.md1_m;
            EXPECT_TRUE(c.significant) << c.md1_m;
        }
}

TEST(RunComparisonTest, AToolTurnedNinetyDegreesSeesNoChangeWhereTheHoleDidNot) {
    // The same hole, the second pass's pad 1 90 degrees round from the first's at every depth.
    // Compared in the earth frame, the gauge hole is unchanged to rounding; in the breakout six
    // pads see the ellipse from other angles, and their spline's error (up to ~2 mm,
    // docs/analysis.md) stays inside the repeatability; 24 arms leave under 0.5 mm.
    for (const int arms : {6, 24}) {
        const AnalysedRun run1 = analyse(makeSyntheticWell(firstRun(arms)));
        SyntheticWellSpec spec2 = firstRun(arms);
        spec2.initialToolAzimuth_deg = 90.0;
        const AnalysedRun run2 = analyse(makeSyntheticWell(spec2));
        const RunComparison r = compare(run1, run2);
        EXPECT_NEAR(r.mapping.shift_m, 0.0, 0.005);
        const double breakoutTolerance = arms == 6 ? 2.5 : 0.5;
        for (const SectionChange& c : r.sections) {
            const bool breakout = inside(c.md1_m, 39.5, 45.5, -0.1);
            const double tolerance = breakout ? breakoutTolerance : 0.05;
            EXPECT_NEAR(c.dmax2_mm - c.dmax1_mm, 0.0, tolerance) << arms << " arms " << c.md1_m;
            EXPECT_NEAR(c.dmin2_mm - c.dmin1_mm, 0.0, tolerance) << arms << " arms " << c.md1_m;
            EXPECT_NEAR(c.deq2_mm - c.deq1_mm, 0.0, tolerance) << arms << " arms " << c.md1_m;
            EXPECT_NEAR(c.maxGrowth_mm, 0.0, tolerance) << arms << " arms " << c.md1_m;
            EXPECT_FALSE(c.significant) << arms << " arms " << c.md1_m;
            if (inside(c.md1_m, 40.0, 45.0, 0.5)) {
                // The major axis stays at 135 in the earth frame.
                EXPECT_NEAR(c.majorAzimuth1_deg, 135.0, 2.0);
                EXPECT_NEAR(c.majorAzimuth2_deg, 135.0, 2.0);
            }
        }
        EXPECT_TRUE(r.agree()) << formatComparisonSummary(r);
        ASSERT_EQ(r.zones.size(), 1u);
        EXPECT_EQ(r.zones[0].kind, ZoneChange::Kind::Unchanged);
    }
}

TEST(RunComparisonTest, ArmsThatDidNotOpenAreNotComparedAndShowNoChange) {
    // AnalysedRun 2's arms stay at 55 mm (a 110 mm reading in a 215.9 mm hole) over 60-70 m.
    const AnalysedRun run1 = analyse(makeSyntheticWell(firstRun()));
    SyntheticWellSpec spec2 = firstRun();
    spec2.closedTop_m = 60.0;
    spec2.closedBottom_m = 70.0;
    spec2.closedRadius_mm = 55.0;
    const AnalysedRun run2 = analyse(makeSyntheticWell(spec2));
    ASSERT_EQ(run2.analysis.armsNotOpen.size(), 1u);
    const RunComparison r = compare(run1, run2);
    std::size_t closed = 0;
    for (const SectionChange& c : r.sections) {
        if (c.md1_m >= 60.0 - 1e-9 && c.md1_m <= 70.0 + 1e-9) {
            EXPECT_EQ(c.notCompared, NotCompared::ArmsNotOpen2) << c.md1_m;
            EXPECT_TRUE(std::isnan(c.deq2_mm));
            EXPECT_FALSE(c.significant);
            ++closed;
        } else {
            EXPECT_TRUE(c.compared()) << c.md1_m;
        }
    }
    EXPECT_EQ(closed, 201u);
    EXPECT_EQ(r.notCompared[static_cast<int>(NotCompared::ArmsNotOpen2)], 201u);
    EXPECT_EQ(r.significant, 0u);
    EXPECT_TRUE(r.agree());
    for (const ZoneChange& z : r.zones) EXPECT_EQ(z.kind, ZoneChange::Kind::Unchanged);
    EXPECT_NE(formatComparisonSummary(r).find("201 run 2 arms not open"), std::string::npos)
        << formatComparisonSummary(r);
}

TEST(RunComparisonTest, IdenticalRunsGiveZeroChange) {
    const AnalysedRun run1 = analyse(makeSyntheticWell(firstRun()));
    const AnalysedRun run2 = analyse(makeSyntheticWell(firstRun()));
    const RunComparison r = compare(run1, run2);
    // The refined shift is zero to Brent's tolerance (micrometres), so the sections read back
    // from run 2 are the same to well under the CSV's 0.01 mm.
    EXPECT_NEAR(r.mapping.shift_m, 0.0, 1e-5);
    ASSERT_EQ(r.sections.size(), run1.analysis.sections.size());
    for (const SectionChange& c : r.sections) {
        EXPECT_NEAR(c.deq2_mm - c.deq1_mm, 0.0, 1e-3);
        EXPECT_NEAR(c.dmax2_mm - c.dmax1_mm, 0.0, 1e-3);
        EXPECT_NEAR(c.maxGrowth_mm, 0.0, 1e-3);
        EXPECT_TRUE(std::isnan(c.maxGrowthAzimuth_deg));
        EXPECT_EQ(c.class1, c.class2);
    }
    EXPECT_TRUE(r.agree());
    EXPECT_EQ(r.classChanges, 0u);
    EXPECT_NEAR(r.volume2_m3, r.volume1_m3, 1e-6);
    // Written, every difference reads 0.00 (never -0.00).
    std::ostringstream csv;
    writeComparisonCsv(csv, r);
    EXPECT_EQ(csv.str().find("-0.00"), std::string::npos);
}

TEST(RunComparisonTest, RunsWithoutOverlapAreAnError) {
    const AnalysedRun run1 = analyse(makeSyntheticWell(firstRun()));
    SyntheticWellSpec spec2 = firstRun();
    spec2.top_m = 400.0;
    const AnalysedRun run2 = analyse(makeSyntheticWell(spec2));
    EXPECT_THROW((void)compare(run1, run2), std::runtime_error);
    RunComparisonOptions given;  // a shift given: still no depth of run 1 in run 2
    given.mapping.given = true;
    EXPECT_THROW((void)compareRuns(run1.compared(), run2.compared(), given), std::runtime_error);
}

TEST(RunComparisonTest, AnUnorientedRunComparesOrientationFreeQuantitiesAndSaysSo) {
    const AnalysedRun run1 = analyse(makeSyntheticWell(firstRun()));
    SyntheticWellSpec spec2 = firstRun();
    spec2.features[0].dmax_mm = 255.9;
    io::SectionTable t2 = makeSyntheticWell(spec2);
    t2.p1az_deg.clear();
    t2.rb_deg.clear();
    const AnalysedRun run2 = analyse(std::move(t2));
    const RunComparison r = compare(run1, run2);
    EXPECT_TRUE(r.unoriented2);
    EXPECT_EQ(r.oriented, 0u);
    for (const SectionChange& c : r.sections) {
        EXPECT_FALSE(c.oriented);
        EXPECT_TRUE(std::isnan(c.maxGrowth_mm));
        EXPECT_TRUE(std::isnan(c.majorAzimuth2_deg));
        if (inside(c.md1_m, 40.0, 45.0, 0.1)) {
            EXPECT_NEAR(c.dmax2_mm - c.dmax1_mm, 10.0, 2.5);
        }
    }
    std::ostringstream csv;
    writeComparisonCsv(csv, r);
    EXPECT_NE(csv.str().find("azimuth unknown: run 2 not oriented"), std::string::npos);
    EXPECT_NE(formatComparisonSummary(r).find("compared orientation-free quantities only"),
              std::string::npos);
}

TEST(RunComparisonTest, EachRunsReadingInCasingIsRemovedAsItsBias) {
    // Both runs start in 7 in 17 lb/ft casing (ID 166.07 mm) to 20 m; run 2 reads every
    // radius 1 mm long (every diameter 2 mm wide). Its casing check says +2 mm, and with it
    // removed the runs agree to rounding.
    SyntheticWellSpec spec = firstRun();
    spec.features.push_back({Kind::Undergauge, 0.0, 20.0, 166.07, 166.07, 0.0, 0.0});
    io::CasingString casing;
    casing.bottom_m = 20.0;
    casing.size_mm = 177.8;
    casing.innerDiameter_mm = 166.07;
    io::SectionTable t1 = makeSyntheticWell(spec);
    t1.casing.push_back(casing);
    io::SectionTable t2 = t1;
    for (double& r : t2.radius_mm) r += 1.0;
    const AnalysedRun run1 = analyse(std::move(t1));
    const AnalysedRun run2 = analyse(std::move(t2));
    const RunComparison r = compare(run1, run2);
    EXPECT_NEAR(r.bias1.offset_mm, kInscribed * 166.07 - 166.07, 0.05);
    EXPECT_NEAR(r.bias2.offset_mm - r.bias1.offset_mm, 2.0 * kInscribed, 0.05);
    EXPECT_GT(r.notCompared[static_cast<int>(NotCompared::Cased1)], 390u);
    for (const SectionChange& c : r.sections) {
        if (!c.compared()) continue;
        EXPECT_NEAR(c.dmax2_mm - c.dmax1_mm, 0.0, 0.1) << c.md1_m;
        EXPECT_NEAR(c.maxGrowth_mm, 0.0, 0.1) << c.md1_m;
    }
    EXPECT_TRUE(r.agree());
    EXPECT_NE(formatComparisonSummary(r).find("mm removed (reading in casing"), std::string::npos);
}

TEST(RunComparisonTest, TheOutlineGateSkipsOnlySectionsWhoseOutlinesAreUnchanged) {
    // The pair of the first test, its second pass also 90 degrees round: compared with the
    // gate `compare` uses (diameters within 1.5 mm, axis within 10 degrees) and without it.
    const AnalysedRun run1 = analyse(makeSyntheticWell(firstRun(24)));
    SyntheticWellSpec spec2 = firstRun(24);
    spec2.depthOffset_m = 0.35;
    spec2.initialToolAzimuth_deg = 90.0;
    spec2.features[0].dmax_mm = 255.9;
    spec2.features.push_back({Kind::Washout, 100.0, 102.0, 265.9, 265.9, 0.0, 0.0});
    const AnalysedRun run2 = analyse(makeSyntheticWell(spec2));
    const RunComparison all = compare(run1, run2);
    const RunComparison gated = compare(run1, run2, kImagerRepeatability95_mm, kCompareOutlineGate);
    EXPECT_EQ(all.outlinesSkipped, 0u);
    EXPECT_DOUBLE_EQ(gated.outlineGate_mm, 1.5);
    ASSERT_EQ(gated.sections.size(), all.sections.size());
    EXPECT_EQ(gated.oriented + gated.outlinesSkipped, all.oriented);
    EXPECT_GT(gated.outlinesSkipped, 9 * gated.oriented);  // the hole is mostly unchanged
    for (std::size_t k = 0; k < gated.sections.size(); ++k) {
        const SectionChange& g = gated.sections[k];
        const SectionChange& a = all.sections[k];
        // Everything orientation-free is the same, and so is every outline compared.
        EXPECT_EQ(g.deq2_mm - g.deq1_mm, a.deq2_mm - a.deq1_mm);
        EXPECT_EQ(g.significant, a.significant);
        if (inside(g.md1_m, 40.0, 45.0, 0.1) || inside(g.md1_m, 100.0, 102.0, 0.1)) {
            ASSERT_TRUE(g.oriented) << g.md1_m;
            EXPECT_FALSE(g.outlineSkipped);
        }
        if (g.oriented) {
            EXPECT_EQ(g.maxGrowth_mm, a.maxGrowth_mm) << g.md1_m;
            EXPECT_TRUE(g.maxGrowthAzimuth_deg == a.maxGrowthAzimuth_deg ||
                        (std::isnan(g.maxGrowthAzimuth_deg) && std::isnan(a.maxGrowthAzimuth_deg)));
        } else {
            // Skipped: no growth reported, and where it was compared in full it was within
            // the gate (the turned tool reads the unchanged hole alike).
            ASSERT_TRUE(g.outlineSkipped) << g.md1_m;
            EXPECT_TRUE(std::isnan(g.maxGrowth_mm));
            EXPECT_TRUE(std::isnan(g.maxGrowthAzimuth_deg));
            EXPECT_LE(std::abs(a.maxGrowth_mm), gated.outlineGate_mm) << g.md1_m;
            if (!inside(g.md1_m, 39.5, 45.5, -0.1) && !inside(g.md1_m, 99.5, 102.5, -0.1)) {
                EXPECT_NEAR(a.maxGrowth_mm, 0.0, 0.05) << g.md1_m;
            }
        }
    }
    EXPECT_EQ(gated.growth.change, all.growth.change);
    EXPECT_EQ(gated.growth.md1_m, all.growth.md1_m);
    std::ostringstream csv;
    writeComparisonCsv(csv, gated, 2);
    EXPECT_NE(csv.str().find(",outline not compared: diameters within 1.50 mm and major axis "
                             "within 10 deg\n"),
              std::string::npos);
    EXPECT_NE(formatComparisonSummary(gated).find("more oriented, their outlines not compared"),
              std::string::npos)
        << formatComparisonSummary(gated);
    // Written on one thread or on three, the same text.
    std::ostringstream one, three;
    writeComparisonCsv(one, gated, 1);
    writeComparisonCsv(three, gated, 3);
    EXPECT_EQ(one.str(), csv.str());
    EXPECT_EQ(three.str(), csv.str());
}

TEST(RunComparisonTest, ABreakoutThatTurnedOpensTheOutlineGate) {
    // Run 2's breakout has the same size but its axis at 45 degrees instead of 135: no diameter
    // changes, so only the axis opens the gate. The wall moved out at 45 (and 225) by the
    // semi-axes' difference, (245.9 - 217.9) / 2 = 14 mm.
    const AnalysedRun run1 = analyse(makeSyntheticWell(firstRun(24)));
    SyntheticWellSpec spec2 = firstRun(24);
    spec2.features[0].majorAzimuth_deg = 45.0;
    const AnalysedRun run2 = analyse(makeSyntheticWell(spec2));
    const RunComparison r = compare(run1, run2, kImagerRepeatability95_mm, kCompareOutlineGate);
    std::size_t turned = 0;
    for (const SectionChange& c : r.sections) {
        if (!inside(c.md1_m, 40.0, 45.0, 0.1)) continue;
        ++turned;
        EXPECT_FALSE(c.significant) << c.md1_m;
        ASSERT_TRUE(c.oriented) << c.md1_m;
        EXPECT_NEAR(c.maxGrowth_mm, 14.0, 0.6) << c.md1_m;
        EXPECT_NEAR(std::fmod(c.maxGrowthAzimuth_deg, 180.0), 45.0, 7.5) << c.md1_m;
    }
    EXPECT_GT(turned, 90u);
    EXPECT_NEAR(r.growth.change, 14.0, 0.6);
}

TEST(RunComparisonTest, IdenticalRunsUnderTheGateCompareNoOutlineAndSaySo) {
    const AnalysedRun run1 = analyse(makeSyntheticWell(firstRun()));
    const AnalysedRun run2 = analyse(makeSyntheticWell(firstRun()));
    const RunComparison r = compare(run1, run2, kImagerRepeatability95_mm, kCompareOutlineGate);
    EXPECT_EQ(r.oriented, 0u);
    EXPECT_EQ(r.outlinesSkipped, r.compared);
    EXPECT_TRUE(std::isnan(r.growth.change));
    // Both runs are oriented: the skipped outlines are no "azimuth unknown".
    EXPECT_FALSE(r.unoriented1);
    EXPECT_FALSE(r.unoriented2);
    const std::string summary = formatComparisonSummary(r);
    EXPECT_NE(summary.find("wall growth by azimuth not compared (the outlines of " +
                           std::to_string(r.compared) +
                           " oriented sections skipped: diameters within 1.50 mm and major axis "
                           "within 10 deg)"),
              std::string::npos)
        << summary;
    EXPECT_EQ(summary.find("azimuths: unknown"), std::string::npos) << summary;
    EXPECT_TRUE(r.agree());
}

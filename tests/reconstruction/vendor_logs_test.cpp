// Logs named the way other vendors name their curves, written by the test and read by the
// one loading recipe every verb uses (docs/formats.md, "Curve roles").
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "io/log_reader.h"
#include "reconstruction/analysis/pick_comparison.h"
#include "reconstruction/analysis/well_analysis.h"
#include "reconstruction/load/load_well.h"
#include "test_support.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {

// A LAS 2.0 file: `curves` are "MNEM.UNIT : description" lines, `row(md)` one data line
// (without the depth) for each depth from `top` to `bottom` by `step` metres.
std::string writeLas(const std::string& name, const std::vector<std::string>& curves, double top,
                     double bottom, double step, const std::function<std::string(double)>& row,
                     const std::string& parameters = "") {
    const std::string path = test::scratch(name).string();
    std::ofstream out(path);
    out << "~Version\n VERS. 2.0 :\n WRAP. NO :\n~Well\n STRT.M " << top << " :\n STOP.M " << bottom
        << " :\n STEP.M " << step << " :\n NULL. -999.25 :\n WELL. VENDOR TEST :\n";
    out << "~Curve\n DEPT.M : depth\n";
    for (const std::string& c : curves) out << " " << c << "\n";
    if (!parameters.empty()) out << "~Parameter\n" << parameters;
    out << "~A\n";
    const int rows = static_cast<int>(std::lround((bottom - top) / step)) + 1;
    for (int i = 0; i < rows; ++i) {
        const double md = top + step * i;
        out << md << " " << row(md) << "\n";
    }
    return path;
}

WellAnalysis analyse(const std::string& path, const LoadOptions& options = {}) {
    const LoadedWell well = loadWell(WellSource{path, {}, {}, {}}, options);
    return analyseWell(*well.geometry, AnalysisOptions{});
}

double angleDiff180(double a, double b) {
    const double d = std::fmod(std::abs(a - b), 180.0);
    return std::min(d, 180.0 - d);
}

}  // namespace

// A Weatherford CMI eight-pad imager log: pad-pair diameters DI26 and DI48, pad-1 azimuth IAP1,
// relative bearing IRBR, tilt ITLT, hole azimuth IAZT. DI26 is the long axis, so with pad 1 at
// 10 degrees the major axis lies along pad 2, at 10 + 45 = 55 degrees.
TEST(VendorLogsTest, EightPadImagerIsReadWithItsPadGeometry) {
    const std::string path = writeLas(
        "cmi_like.las",
        {"IECX.MM : MIE Caliper X", "IECY.MM : MIE Caliper Y", "IRBR.DEG : Relative Bearing",
         "ITLT.DEG : Borehole Tilt", "IAP1.DEG : Azimuth of Reference",
         "IAZT.DEG : Borehole Azimuth (True)", "DI26.MM : Imager Diameter 2 - 6",
         "DI48.MM : Imager Diameter 4 - 8", "BIT.MM : Bit size"},
        100.0, 120.0, 0.1, [](double) { return std::string("175 175 10 0 10 0 190 160 159"); });

    const io::LogInfo info = io::describeLog(path, io::ReadOptions{});
    EXPECT_EQ(info.arms, 4);
    EXPECT_NE(info.armSource.find("DI26 DI48"), std::string::npos) << info.armSource;
    EXPECT_NE(info.armSource.find("a tool with 8 pads, arm 1 45 deg clockwise of pad 1"),
              std::string::npos)
        << info.armSource;
    std::map<std::string, const io::CurveInfo*> curves;
    for (const io::CurveInfo& c : info.curves) curves[c.mnemonic] = &c;
    ASSERT_EQ(curves.size(), 10u);
    EXPECT_EQ(curves["IAP1"]->role, "pad-1 azimuth");
    EXPECT_EQ(curves["IRBR"]->role, "relative bearing");
    EXPECT_EQ(curves["ITLT"]->role, "deviation");
    EXPECT_EQ(curves["IAZT"]->role, "hole azimuth");
    EXPECT_EQ(curves["IECX"]->role, "caliper (not used for the arms)");
    EXPECT_EQ(curves["DI26"]->description, "Imager Diameter 2 - 6");

    const WellAnalysis a = analyse(path);
    ASSERT_GT(a.sections.size(), 100u);
    for (const SectionResult& r : a.sections) {
        // Four knots: the closed spline bulges a little between them.
        EXPECT_NEAR(r.dmax_mm, 190.0, 1.5);
        EXPECT_NEAR(r.dmin_mm, 160.0, 1.5);
        EXPECT_LT(angleDiff180(r.majorAzimuth_deg, 55.0), 0.5) << r.majorAzimuth_deg;
    }
}

// Path curves under their long names: the well leans east, not straight down.
TEST(VendorLogsTest, InclinationAndAzimuthUnderTheirLongNamesMakeThePath) {
    const std::string path = writeLas(
        "long_path_names.las",
        {"R1.MM :", "R2.MM :", "R3.MM :", "R4.MM :", "R5.MM :", "R6.MM :", "P1AZ.DEG :",
         "INCLINATION.DEG : hole inclination", "AZIMUTH.DEG : hole azimuth"},
        0.0, 100.0, 0.5, [](double) { return std::string("100 100 100 100 100 100 0 30 90"); });
    const WellAnalysis a = analyse(path);
    const SectionResult& bottom = a.sections[a.sections.size() - 1];
    EXPECT_NEAR(bottom.inc_deg, 30.0, 1e-6);
    EXPECT_NEAR(bottom.azi_deg, 90.0, 1e-6);
    // 100 m drilled along 30 degrees, tied to a vertical station at the top.
    EXPECT_GT(bottom.east_m, 40.0);
    EXPECT_NEAR(bottom.north_m, 0.0, 1e-6);
}

// A single-diameter caliper (CAL1 of the welly corpus): two pads, the circle through them.
TEST(VendorLogsTest, SingleDiameterCaliperGivesTwoPads) {
    const std::string path = writeLas("cal1.las", {"GR.GAPI :", "CAL1.IN : caliper"}, 10.0, 20.0,
                                      0.5, [](double) { return std::string("80 8.5"); });
    const io::LogInfo info = io::describeLog(path, io::ReadOptions{});
    EXPECT_EQ(info.arms, 2);
    const WellAnalysis a = analyse(path);
    // The circle through both pads, sampled as a 48-gon: 0.14 % less area.
    EXPECT_NEAR(a.sections[0].equivalentDiameter_mm, 8.5 * 25.4, 0.5);
}

// No caliper curve at all: described with a warning that says how to name them.
TEST(VendorLogsTest, NoCaliperCurveIsAWarningThatSaysWhatToDo) {
    const std::string path = writeLas("no_caliper.las", {"GR.GAPI : gamma", "RHOB.G/C3 :"}, 10.0,
                                      20.0, 0.5, [](double) { return std::string("80 2.3"); });
    const io::LogInfo info = io::describeLog(path, io::ReadOptions{});
    EXPECT_EQ(info.arms, 0);
    bool warned = false;
    for (const io::Warning& w : info.diagnostics.warnings)
        warned = warned || w.message.find("no caliper curve recognised") != std::string::npos;
    EXPECT_TRUE(warned);
    EXPECT_THROW(analyse(path), std::exception);
}

namespace {
// Six radii of an ellipse with semi-axes a (at `axis` degrees clockwise from arm 1) and b,
// arms 60 degrees apart.
std::string ellipseRadii(double a, double b, double axis = 0.0) {
    std::string out;
    for (int k = 0; k < 6; ++k) {
        const double t = (k * 60.0 - axis) * 3.14159265358979323846 / 180.0;
        const double r = a * b / std::hypot(b * std::cos(t), a * std::sin(t));
        out += std::to_string(r) + " ";
    }
    return out;
}
}  // namespace

// Six arms, no pad-1 azimuth and no relative bearing: the breakout is measured, its azimuth is
// not invented (it used to come out as 0 degrees, arm 1 taken as north, with an SD of 0).
TEST(VendorLogsTest, NoOrientationLeavesEveryAzimuthEmpty) {
    const std::string path =
        writeLas("no_orientation.las",
                 {"R1.MM :", "R2.MM :", "R3.MM :", "R4.MM :", "R5.MM :", "R6.MM :", "BS.MM :"},
                 50.0, 70.0, 0.1, [](double) { return ellipseRadii(100.0, 85.0) + "170"; });
    const WellAnalysis a = analyse(path);
    EXPECT_EQ(a.unorientedSections, a.sections.size());
    for (const SectionResult& r : a.sections) {
        EXPECT_NEAR(r.dmax_mm, 200.0, 1.0);
        EXPECT_NEAR(r.dmin_mm, 170.0, 1.0);
        EXPECT_EQ(r.cls, BoreholeClass::Breakout);
        EXPECT_TRUE(std::isnan(r.majorAzimuth_deg));
        EXPECT_TRUE(std::isnan(r.majorFromHighSide_deg));
        EXPECT_TRUE(std::isnan(r.centreOffsetAzimuth_deg));
    }
    ASSERT_EQ(a.zones.size(), 1u);
    EXPECT_TRUE(std::isnan(a.zones[0].meanAzimuth_deg));
    EXPECT_TRUE(std::isnan(a.zones[0].circularSd_deg));
    EXPECT_EQ(a.breakouts.zoneCount, 1u);
    EXPECT_TRUE(std::isnan(a.breakouts.shmaxAzimuth_deg));
    EXPECT_EQ(a.breakouts.quality, 'E');

    // The same log with a pad-1 azimuth of 30 degrees: the major axis lies along arm 1, at 30.
    const std::string oriented = writeLas(
        "oriented.las",
        {"R1.MM :", "R2.MM :", "R3.MM :", "R4.MM :", "R5.MM :", "R6.MM :", "BS.MM :", "P1AZ.DEG :"},
        50.0, 70.0, 0.1, [](double) { return ellipseRadii(100.0, 85.0) + "170 30"; });
    const WellAnalysis b = analyse(oriented);
    EXPECT_EQ(b.unorientedSections, 0u);
    ASSERT_EQ(b.zones.size(), 1u);
    EXPECT_NEAR(b.zones[0].meanAzimuth_deg, 30.0, 0.5);
}

// A six-arm tool turning 120 degrees over a 10 m breakout whose long axis stays at 40 degrees in
// the earth frame: the strongest evidence of a breakout, not a reason to reject it (the
// four-arm rule "tool turning less than 45 degrees in any 5 m" used to make it in_gauge).
// The same tool whose elongation turns with it (an artefact of the tool) is rejected.
TEST(VendorLogsTest, TurningSixArmToolStillSeesABreakoutFixedInTheEarth) {
    auto log = [](const std::string& name, bool fixedInEarth) {
        return writeLas(
            name,
            {"R1.MM :", "R2.MM :", "R3.MM :", "R4.MM :", "R5.MM :", "R6.MM :", "BS.MM :",
             "P1AZ.DEG :"},
            0.0, 30.0, 0.1, [fixedInEarth](double md) {
                const double p1az = md < 10.0 ? 0.0 : md > 20.0 ? 120.0 : 12.0 * (md - 10.0);
                const bool zone = md >= 10.0 && md <= 20.0;
                const double axis = fixedInEarth ? 40.0 - p1az : 0.0;
                return (zone ? ellipseRadii(100.0, 85.0, axis) : ellipseRadii(85.0, 85.0)) +
                       "170 " + std::to_string(p1az);
            });
    };
    const WellAnalysis fixed = analyse(log("turning_tool_fixed_breakout.las", true));
    ASSERT_EQ(fixed.zones.size(), 1u);
    EXPECT_EQ(fixed.zones[0].kind, BoreholeClass::Breakout);
    EXPECT_NEAR(fixed.zones[0].top_m, 9.95, 0.06);
    EXPECT_NEAR(fixed.zones[0].bottom_m, 20.05, 0.06);
    EXPECT_NEAR(fixed.zones[0].meanAzimuth_deg, 40.0, 0.5);

    const WellAnalysis artefact = analyse(log("turning_tool_artefact.las", false));
    EXPECT_TRUE(artefact.zones.empty());
}

// Breakouts picked on an image log beside the caliper's: a six-arm log with a breakout at 30
// degrees over 55-65 m; picks at 31 and at 208 degrees (the other side) agree within 2, one
// outside the log, one tensile fracture not compared.
TEST(VendorLogsTest, ImageLogPicksAreComparedWithTheCaliperBreakouts) {
    const std::string path = writeLas(
        "picked.las",
        {"R1.MM :", "R2.MM :", "R3.MM :", "R4.MM :", "R5.MM :", "R6.MM :", "BS.MM :", "P1AZ.DEG :"},
        50.0, 70.0, 0.1, [](double md) {
            const bool zone = md >= 55.0 && md <= 65.0;
            return (zone ? ellipseRadii(100.0, 85.0) : ellipseRadii(85.0, 85.0)) + "170 30";
        });
    const WellAnalysis a = analyse(path);
    ASSERT_EQ(a.zones.size(), 1u);
    std::vector<io::Pick> picks(4);
    picks[0] = {56.0, 58.0, 31.0, "BREAKOUT", 2};
    picks[1] = {60.0, 60.0, 208.0, "", 3};
    picks[2] = {90.0, 91.0, 40.0, "BREAKOUT", 4};
    picks[3] = {52.0, 52.0, 120.0, "DITF", 5};
    const PicksComparison c = comparePicks(picks, a);
    EXPECT_EQ(c.outsideLog, 1u);
    EXPECT_EQ(c.breakoutPicks, 2u);
    EXPECT_EQ(c.inCaliperBreakout, 2u);
    EXPECT_EQ(c.compared, 2u);
    EXPECT_NEAR(c.picks[0].difference_deg, 1.0, 0.5);
    EXPECT_NEAR(c.picks[1].difference_deg, 2.0, 0.5);
    EXPECT_NEAR(c.meanDifference_deg, 1.5, 0.5);
    EXPECT_EQ(c.within20, 2u);
    EXPECT_EQ(c.caliperZonesPicked, 1u);
    EXPECT_EQ(c.picks[3].caliperClass, BoreholeClass::InGauge);
    EXPECT_TRUE(std::isnan(c.picks[3].difference_deg));
    const std::string text = formatPicksComparison(c);
    EXPECT_NE(text.find("mean difference 1.5 deg over 2 picks"), std::string::npos) << text;
    EXPECT_NE(text.find("outside the log"), std::string::npos) << text;
    EXPECT_NE(text.find("not a breakout"), std::string::npos) << text;
}

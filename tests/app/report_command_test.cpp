// caliper3d report: the verb end to end on synthetic wells with known answers
// (synth profiles, an analytic survey) and on the real FMI log.
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_run.h"
#include "csv_table.h"
#include "test_support.h"

using caliper3d::test::CommandRun;
using caliper3d::test::Csv;
using caliper3d::test::parseCsv;
using caliper3d::test::readCsv;
using caliper3d::test::runCaliper3d;
using caliper3d::test::scratch;

namespace {

std::string synth(const std::string& profile, double length, double step) {
    const std::string log = scratch("report_" + profile + ".txt").string();
    const CommandRun r = runCaliper3d("synth -o " + log + " --profile " + profile + " --length " +
                                      std::to_string(length) + " --step " + std::to_string(step));
    EXPECT_EQ(r.status, 0) << r.output;
    return log;
}

}  // namespace

TEST(ReportCommandTest, KeyseatProfileIsClassedOnItsIntervalWithZones) {
    // synth profile "keyseat" (reconstruction/synthetic/synthetic_well.h): over 0.6-0.8 L
    // an ellipse with its major axis on the high side of a build section.
    const std::string log = synth("keyseat", 300.0, 0.25);
    const auto csv = scratch("report_keyseat.csv");
    const auto zones = scratch("report_keyseat_zones.csv");
    const CommandRun r = runCaliper3d("report " + log + " -o " + csv.string() + " --zones " +
                                      zones.string() + " --bit-size 215.9mm");
    ASSERT_EQ(r.status, 0) << r.output;
    const Csv report = readCsv(csv);
    const std::vector<std::string> required = {"md_m",        "tvd_m",
                                               "north_m",     "east_m",
                                               "inc_deg",     "azi_deg",
                                               "dmin_mm",     "dmax_mm",
                                               "ellipticity", "major_azimuth_deg",
                                               "area_mm2",    "centre_offset_mm",
                                               "class"};
    ASSERT_GE(report.names.size(), required.size());
    for (std::size_t k = 0; k < required.size(); ++k) EXPECT_EQ(report.names[k], required[k]);
    ASSERT_EQ(report.rows.size(), 1201u);
    std::size_t keyseats = 0;
    for (std::size_t i = 0; i < report.rows.size(); ++i) {
        const double md = report.number(i, "md_m");
        const std::string& cls = report.rows[i].at("class");
        if (md > 181.0 && md < 239.0) {
            EXPECT_EQ(cls, "keyseat") << md;
        } else if (md < 179.0 || md > 241.0) {
            EXPECT_EQ(cls, "in_gauge") << md;
        }
        keyseats += cls == "keyseat";
        const double azimuth = report.number(i, "major_azimuth_deg");
        if (!std::isnan(azimuth)) {
            EXPECT_GE(azimuth, 0.0);
            EXPECT_LT(azimuth, 180.0);
        }
    }
    EXPECT_GT(keyseats, 230u);
    const Csv zoneTable = readCsv(zones);
    ASSERT_EQ(zoneTable.rows.size(), 1u);
    EXPECT_EQ(zoneTable.rows[0].at("kind"), "keyseat");
    EXPECT_NEAR(zoneTable.number(0, "top_m"), 180.0, 0.5);
    EXPECT_NEAR(zoneTable.number(0, "bottom_m"), 240.0, 0.5);
    EXPECT_NE(r.output.find("wrote " + csv.string()), std::string::npos) << r.output;
}

TEST(ReportCommandTest, SurveyReplacesTheLogsPathAndMatchesTheExactArc) {
    // A vertical log, and a survey that builds at 3 deg/30 m towards east from
    // the surface: the path is a circular arc of radius R = 30 / (3 deg in
    // radians) = 572.958 m; at 100 m the hole is 10 deg over, TVD = R sin 10,
    // east = R (1 - cos 10).
    const std::string log = synth("circle", 100.0, 0.5);
    const auto survey = scratch("report_build_survey.csv");
    {
        std::ofstream out(survey);
        out << "MD,Inc,Azi\n";
        for (int md = 0; md <= 100; md += 10) out << md << "," << md * 0.1 << ",90\n";
    }
    const auto csv = scratch("report_survey.csv");
    const CommandRun r =
        runCaliper3d("report " + log + " -o " + csv.string() + " --survey " + survey.string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("path from " + survey.string()), std::string::npos) << r.output;
    const Csv report = readCsv(csv);
    ASSERT_EQ(report.rows.size(), 201u);
    const std::size_t last = report.rows.size() - 1;
    const double radius = 30.0 / (3.0 * M_PI / 180.0);
    const double theta = 10.0 * M_PI / 180.0;
    EXPECT_NEAR(report.number(last, "md_m"), 100.0, 1e-9);
    EXPECT_NEAR(report.number(last, "tvd_m"), radius * std::sin(theta), 1e-3);
    EXPECT_NEAR(report.number(last, "east_m"), radius * (1.0 - std::cos(theta)), 1e-3);
    EXPECT_NEAR(report.number(last, "north_m"), 0.0, 1e-3);
    EXPECT_NEAR(report.number(last, "inc_deg"), 10.0, 1e-3);
    EXPECT_NEAR(report.number(last, "dls_deg_per_30m"), 3.0, 1e-3);
    // Half way between stations too (interpolated along the arc).
    EXPECT_NEAR(report.number(10, "inc_deg"), 0.5, 1e-3);  // 5 m
}

TEST(ReportCommandTest, ASurveyWhoseTvdDisagreesWithItsAnglesIsWarnedAbout) {
    // The 3 deg/30 m build of the test above, with a TVD column that ignores the
    // build (TVD = MD): minimum curvature gives 99.493 m at 100 m, 0.507 m less.
    const std::string log = synth("circle", 100.0, 0.5);
    const auto survey = scratch("report_tvd_survey.csv");
    {
        std::ofstream out(survey);
        out << "MD,Inc,Azi,TVD\n";
        for (int md = 0; md <= 100; md += 10) out << md << "," << md * 0.1 << ",90," << md << "\n";
    }
    const CommandRun r =
        runCaliper3d("report " + log + " -o " + scratch("report_tvd.csv").string() + " --survey " +
                     survey.string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(
        r.output.find(survey.string() + ":1: warning: the positions the file writes disagree with "
                                        "minimum curvature"),
        std::string::npos)
        << r.output;
    EXPECT_NE(
        r.output.find(
            "TVD within 0.507 m of minimum curvature over 11 stations (largest at MD 100.00 m)"),
        std::string::npos)
        << r.output;
    const CommandRun info = runCaliper3d("info " + survey.string());
    EXPECT_EQ(info.status, 0) << info.output;
    EXPECT_NE(info.output.find("check:     TVD within 0.507 m"), std::string::npos) << info.output;
}

TEST(ReportCommandTest, WellheadLasAndStandardOutput) {
    const std::string log = synth("example", 100.0, 0.5);
    const auto las = scratch("report_example.las");
    std::filesystem::remove(las);
    const CommandRun r = runCaliper3d("report " + log + " -o - --step 10 --las " + las.string() +
                                          " --wellhead 512300.5,6801200.25,25 --bit-size 8.5in",
                                      false);
    ASSERT_EQ(r.status, 0) << r.output;
    std::istringstream in(r.output);
    const Csv report = parseCsv(in);
    ASSERT_EQ(report.rows.size(), 11u) << r.output;
    EXPECT_EQ(report.names.back(), "tvdss_m");
    EXPECT_NEAR(report.number(0, "easting_m"), 512300.5, 1e-9);
    EXPECT_NEAR(report.number(0, "northing_m"), 6801200.25, 1e-9);
    EXPECT_NEAR(report.number(0, "tvdss_m"), -25.0, 1e-9);
    std::ifstream lasIn(las);
    std::string first;
    std::getline(lasIn, first);
    EXPECT_EQ(first, "~Version information");
}

TEST(ReportCommandTest, ZoneTableOnStandardOutputAndOnlyOneDash) {
    // The washout profile: one washout zone over 0.4-0.6 L, a circle with no major axis.
    const std::string log = synth("washout", 100.0, 0.5);
    const auto csv = scratch("report_zones_stdout.csv");
    const CommandRun r =
        runCaliper3d("report " + log + " -o " + csv.string() + " --zones -", false);
    ASSERT_EQ(r.status, 0) << r.output;
    std::istringstream in(r.output);
    const Csv zones = parseCsv(in);
    ASSERT_EQ(zones.rows.size(), 1u) << r.output;
    EXPECT_EQ(zones.rows[0].at("kind"), "washout");
    EXPECT_NEAR(zones.number(0, "top_m"), 40.0, 0.5);
    EXPECT_EQ(zones.rows[0].at("mean_azimuth_deg"), "");  // round: no azimuth to average
    EXPECT_TRUE(std::filesystem::exists(csv));
    EXPECT_EQ(runCaliper3d("report " + log + " -o - --zones -").status, 2);
}

TEST(ReportCommandTest, BadSurveyIsBadInputNamingItsFileAndLine) {
    const std::string log = synth("circle", 20.0, 0.5);
    const auto survey = scratch("report_bad_survey.csv");
    { std::ofstream(survey) << "MD,Inc,Azi\n0,0,0\n10,abc,0\n20,1,0\n"; }
    const CommandRun r =
        runCaliper3d("report " + log + " -o " + scratch("report_bad.csv").string() + " --survey " +
                     survey.string());
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find(survey.string() + ":3"), std::string::npos) << r.output;
}

TEST(ReportCommandTest, BadUsageExitsTwo) {
    const std::string log = synth("circle", 20.0, 0.5);
    const std::string out = " -o " + scratch("report_usage.csv").string();
    EXPECT_EQ(runCaliper3d("report " + log).status, 2);                              // no -o
    EXPECT_EQ(runCaliper3d("report " + log + " " + log + out).status, 2);            // two wells
    EXPECT_EQ(runCaliper3d("report " + log + out + " --rule washout=3").status, 2);  // unknown rule
    EXPECT_EQ(runCaliper3d("report " + log + out + " --step -1").status, 2);
    EXPECT_EQ(runCaliper3d("report " + log + out + " --interval 30,10").status, 2);
    EXPECT_EQ(runCaliper3d("report " + log + out + " --wellhead 1,2").status, 2);
    EXPECT_EQ(runCaliper3d("report " + log + out + " --casing-od seven").status, 2);
    EXPECT_EQ(runCaliper3d("export " + log + " -o x.iv --survey a.csv --survey b.csv").status, 2);
    const CommandRun rules = runCaliper3d("report --rule list");
    EXPECT_EQ(rules.status, 0);
    EXPECT_NE(rules.output.find("washout_mm=12.7"), std::string::npos) << rules.output;
}

TEST(ReportCommandTest, RuleChangesTheClassification) {
    // The washout profile: a 255.9 mm circle in a 215.9 mm hole (+40 mm). With
    // the washout threshold raised past 40 mm it is no longer a washout.
    const std::string log = synth("washout", 100.0, 0.5);
    const auto csv = scratch("report_rule.csv");
    const CommandRun normal = runCaliper3d("report " + log + " -o " + csv.string());
    ASSERT_EQ(normal.status, 0) << normal.output;
    EXPECT_EQ(readCsv(csv).rows[100].at("class"), "washout");  // 50 m
    const CommandRun raised =
        runCaliper3d("report " + log + " -o " + csv.string() + " --rule washout_mm=45");
    ASSERT_EQ(raised.status, 0) << raised.output;
    EXPECT_EQ(readCsv(csv).rows[100].at("class"), "in_gauge");
}

TEST(ReportCommandTest, RealFmiLogReportsPadAzimuthOffsetNearZero) {
    const auto fmi = caliper3d::test::sharedData() / "real" / "1AA063409108W400_FMI_SONIC_MAIN.las";
    CALIPER3D_REQUIRE_DATA(fmi);
    const auto csv = scratch("report_fmi.csv");
    const CommandRun r =
        runCaliper3d("report " + fmi.string() + " -o " + csv.string() + " --step 1");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_GT(readCsv(csv).rows.size(), 100u);
    const std::string key = "P1AZ - (HAZI+RB): mean ";
    const std::size_t at = r.output.find(key);
    ASSERT_NE(at, std::string::npos) << r.output;
    EXPECT_LT(std::abs(std::stod(r.output.substr(at + key.size()))), 1.5) << r.output;
}

TEST(ReportCommandTest, ReportAndExportBothSayHowManyArmsWereInterpolated) {
    // synth profile "stuck-arm": arm 3 reads nothing over 0.4-0.6 L.
    const std::string log = synth("stuck-arm", 20.0, 0.5);
    const CommandRun report =
        runCaliper3d("report " + log + " -o " + scratch("report_stuck.csv").string());
    ASSERT_EQ(report.status, 0) << report.output;
    const std::string counted = "9 arms interpolated on 9 sections";  // 8.0, 8.5, ..., 12.0 m
    EXPECT_NE(report.output.find(counted), std::string::npos) << report.output;
    const CommandRun exported =
        runCaliper3d("export " + log + " -o " + scratch("report_stuck.iv").string());
    ASSERT_EQ(exported.status, 0) << exported.output;
    EXPECT_NE(exported.output.find(log + ": warning: " + counted), std::string::npos)
        << exported.output;
}

TEST(ReportCommandTest, ATwoPadWellReportsRoundSectionsEndToEnd) {
    // synth --arms 2 of the washout profile: one diameter, 215.9 mm, 255.9 mm over 0.4-0.6 L.
    const auto log = scratch("report_two_pads.las");
    const CommandRun made = runCaliper3d("synth -o " + log.string() +
                                         " --profile washout --length 50 --step 0.5 --arms 2");
    ASSERT_EQ(made.status, 0) << made.output;
    const auto csv = scratch("report_two_pads.csv");
    const CommandRun r =
        runCaliper3d("report " + log.string() + " -o " + csv.string() + " --zones -", false);
    ASSERT_EQ(r.status, 0) << r.output;
    std::istringstream zonesText(r.output);
    const Csv zones = parseCsv(zonesText);
    ASSERT_EQ(zones.rows.size(), 1u) << r.output;
    EXPECT_EQ(zones.rows[0].at("kind"), "washout");
    EXPECT_NEAR(zones.number(0, "mean_dmax_mm"), 255.9, 0.01);
    const Csv report = readCsv(csv);
    ASSERT_EQ(report.rows.size(), 101u);
    EXPECT_NEAR(report.number(0, "dmin_mm"), 215.9, 0.01);
    EXPECT_NEAR(report.number(0, "dmax_mm"), 215.9, 0.01);
    EXPECT_EQ(report.rows[0].at("major_azimuth_deg"), "");
    EXPECT_EQ(report.rows[0].at("class"), "in_gauge");
    const CommandRun summary = runCaliper3d("report " + log.string() + " -o " + csv.string());
    EXPECT_NE(summary.output.find("breakouts: not seen by a two-pad tool"), std::string::npos)
        << summary.output;
    EXPECT_EQ(runCaliper3d("synth -o " + log.string() + " --arms 1").status, 2);
}

TEST(ReportCommandTest, RadiiOptionTakesTwoOrMoreNamesOrOneWholeArray) {
    const auto las = scratch("report_array.las");
    {
        std::ofstream out(las);
        out << "~V\n VERS. 2.0 :\n WRAP. NO :\n~C\n DEPT.M :\n MFC[1].IN :\n MFC[2].IN :\n "
               "MFC[3].IN :\n"
               "~A\n10 4 4.5 4\n10.5 4 4.5 4\n";
    }
    const CommandRun array = runCaliper3d("info " + las.string() + " --radii 'MFC[]'");
    EXPECT_EQ(array.status, 0) << array.output;
    EXPECT_NE(array.output.find("arms:      3 from radii MFC[1] MFC[2] MFC[3]"), std::string::npos)
        << array.output;
    const CommandRun two = runCaliper3d("info " + las.string() + " --radii 'MFC[1],MFC[3]'");
    EXPECT_NE(two.output.find("arms:      2 from radii MFC[1] MFC[3]"), std::string::npos)
        << two.output;
    EXPECT_EQ(runCaliper3d("info " + las.string() + " --radii 'MFC[1]'").status, 2);
}

TEST(ReportCommandTest, StarLogIsMeasuredFromTheWellheadAndLeavesUnknownAzimuthEmpty) {
    // The STAR log starts at MD 26.97 m below its kelly bushing and has no HAZI:
    // TVD counts from the wellhead, and north, east and azimuth are no data.
    const auto star =
        caliper3d::test::sharedData() / "real" / "1AA072209208W400_WL_0477502_STAR_FIELD.las";
    CALIPER3D_REQUIRE_DATA(star);
    const auto csv = scratch("report_star.csv");
    const CommandRun r = runCaliper3d("report " + star.string() + " -o " + csv.string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("hole azimuth unknown"), std::string::npos) << r.output;
    const Csv report = readCsv(csv);
    ASSERT_GT(report.rows.size(), 1000u);
    EXPECT_NEAR(report.number(0, "md_m"), 26.9748, 1e-4);
    EXPECT_NEAR(report.number(0, "tvd_m"), 26.9748, 1e-4);  // vertical at the top
    const std::size_t last = report.rows.size() - 1;
    EXPECT_TRUE(std::isnan(report.number(last, "north_m")));
    EXPECT_TRUE(std::isnan(report.number(last, "east_m")));
    EXPECT_TRUE(std::isnan(report.number(last, "azi_deg")));
    EXPECT_LT(report.number(last, "md_m") - report.number(last, "tvd_m"), 0.01);
}

TEST(ReportCommandTest, TieInGivesTheSameTvdWithAndWithoutASurvey) {
    // A vertical log from 27 m, with and without a survey from the wellhead:
    // the same TVD (= MD) on every row.
    const std::string log = scratch("report_tie_in.txt").string();
    {
        std::ofstream out(log);
        for (int i = 0; i <= 40; ++i)
            out << 27.0 + 0.5 * i << " 4.25 4.25 4.25 4.25 4.25 4.25 10 0 0\n";
    }
    const auto survey = scratch("report_tie_in_survey.csv");
    { std::ofstream(survey) << "MD,INC,AZI\n0,0,0\n100,0,0\n"; }
    const auto plain = scratch("report_tie_in.csv"), surveyed = scratch("report_tie_in_s.csv");
    ASSERT_EQ(runCaliper3d("report " + log + " -o " + plain.string()).status, 0);
    const CommandRun r =
        runCaliper3d("report " + log + " -o " + surveyed.string() + " --survey " + survey.string());
    ASSERT_EQ(r.status, 0) << r.output;
    const Csv a = readCsv(plain), b = readCsv(surveyed);
    ASSERT_EQ(a.rows.size(), 41u);
    ASSERT_EQ(b.rows.size(), 41u);
    for (std::size_t i = 0; i < a.rows.size(); ++i) {
        EXPECT_DOUBLE_EQ(a.number(i, "tvd_m"), a.number(i, "md_m"));
        EXPECT_DOUBLE_EQ(b.number(i, "tvd_m"), a.number(i, "tvd_m"));
        EXPECT_DOUBLE_EQ(b.number(i, "north_m"), a.number(i, "north_m"));
        EXPECT_DOUBLE_EQ(b.number(i, "east_m"), a.number(i, "east_m"));
    }
}

// Image-log picks beside the caliper's breakout (the example profile: 60-80 m, axis 135 deg):
// a pick on its other side (317 deg) agrees within 2 deg; one in round hole is not compared.
TEST(ReportCommandTest, PicksAreReportedBesideTheCaliperZones) {
    const std::string log = synth("example", 300.0, 0.1);
    const auto picks = scratch("report_picks_input.csv");
    std::ofstream(picks) << "md,azimuth,type\n70,317,BREAKOUT\n200,40,BREAKOUT\n";
    const auto summary = scratch("report_picks_summary.jsonl");
    const CommandRun r =
        runCaliper3d("report " + log + " -o " + scratch("report_picks.csv").string() + " --picks " +
                     picks.string() + " --summary " + summary.string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("1 of 1 caliper breakout zones picked"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("over 1 picks, 1 within 20 deg"), std::string::npos) << r.output;
    std::ifstream in(summary);
    const std::string line((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(line.find("\"breakouts\":{\"zones\":1"), std::string::npos) << line;
    EXPECT_NE(line.find("\"shmax_azimuth_deg\":45."), std::string::npos) << line;
}

// The same well with its orientation curves left out: the breakout is measured, every azimuth
// is empty (the summary's are null) and the warning says why.
TEST(ReportCommandTest, WithoutOrientationNoAzimuthIsInvented) {
    const std::string log = synth("example", 300.0, 0.1);
    const auto csv = scratch("report_unoriented.csv");
    const auto summary = scratch("report_unoriented_summary.jsonl");
    const CommandRun r =
        runCaliper3d("report " + log + " -o " + csv.string() +
                     " --pad-azimuth none --relative-bearing none --summary " + summary.string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("orientation unknown"), std::string::npos) << r.output;
    const Csv report = readCsv(csv);
    std::size_t breakouts = 0;
    for (std::size_t i = 0; i < report.rows.size(); ++i) {
        EXPECT_TRUE(std::isnan(report.number(i, "major_azimuth_deg")));
        breakouts += report.rows[i].at("class") == "breakout";
    }
    EXPECT_GT(breakouts, 150u);
    std::ifstream in(summary);
    const std::string line((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(line.find("\"mean_azimuth_deg\":null"), std::string::npos) << line;
    EXPECT_NE(line.find("\"shmax_azimuth_deg\":null"), std::string::npos) << line;
}

TEST(ReportCommandTest, CasingFromTheHeaderOrOptionIsCasedWithACalibrationCheck) {
    // 8 5/8 in 32 lb/ft casing to 20 m (API 5CT ID 201.19 mm), read 200 mm by six arms; a
    // 215.9 mm hole below whose arms stay closed at 110 mm over 30-35 m.
    const auto las = scratch("report_casing.las");
    {
        std::ofstream out(las);
        out << "~V\n VERS. 2.0 :\n WRAP. NO :\n~W\n STRT.M 10 :\n STOP.M 40 :\n STEP.M 0.5 :\n"
               "~P\n BS.MM 215.9 :\n CSGL.M 20.0 : Casing bottom logger\n"
               " CSGS.IN 8.625 : Casing size\n CSGW.LB/FT 32 : Casing weight\n"
               "~C\n DEPT.M :\n R1.MM :\n R2.MM :\n R3.MM :\n R4.MM :\n R5.MM :\n R6.MM :\n~A\n";
        for (int i = 0; i <= 60; ++i) {
            const double md = 10.0 + 0.5 * i;
            const double r = md <= 20.0 ? 100.0 : (md >= 30.0 && md <= 35.0 ? 55.0 : 107.95);
            out << md;
            for (int k = 0; k < 6; ++k) out << ' ' << r;
            out << '\n';
        }
    }
    const auto summary = scratch("report_casing.jsonl");
    std::filesystem::remove(summary);
    const CommandRun r =
        runCaliper3d("report " + las.string() + " -o " + scratch("report_casing.csv").string() +
                     " --summary " + summary.string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("0 zones, 11 no data"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("cased hole left out: 10.00-20.50 m"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("reading in casing: median 199.7 mm over 10.00-20.00 m (21 "
                            "sections), nominal ID 201.2 mm, offset -1.5 mm"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("warning: arms not open over 30.00-35.00 m (11 sections)"),
              std::string::npos)
        << r.output;
    const Csv csv = readCsv(scratch("report_casing.csv"));
    ASSERT_EQ(csv.rows.size(), 61u);
    EXPECT_EQ(csv.rows[0].at("class"), "cased");
    EXPECT_NEAR(csv.number(0, "bit_mm"), 201.19, 0.01);
    EXPECT_EQ(csv.rows[21].at("class"), "in_gauge");
    EXPECT_EQ(csv.rows[45].at("class"), "no_data");
    std::ifstream json(summary);
    std::string line;
    ASSERT_TRUE(std::getline(json, line));
    EXPECT_NE(line.find("\"cased\":21"), std::string::npos) << line;
    EXPECT_NE(line.find("\"casing\":[{\"bottom_m\":20.0,\"size_mm\":219.07"), std::string::npos)
        << line;
    EXPECT_NE(line.find("\"arms_not_open\":[{\"top_m\":30.0,\"bottom_m\":35.0,\"sections\":11,"
                        "\"reason\":\"arms not open\"}]"),
              std::string::npos)
        << line;

    // --casing replaces the header's program, once per string.
    const CommandRun given =
        runCaliper3d("report " + las.string() + " -o " + scratch("report_casing2.csv").string() +
                     " --casing 15,13.375in,68lb/ft --casing 12,8.625in,200mm");
    ASSERT_EQ(given.status, 0) << given.output;
    EXPECT_NE(given.output.find("shoe at 12.00 m; nominal ID 200.00 mm (given)"), std::string::npos)
        << given.output;
    EXPECT_NE(given.output.find("shoe at 15.00 m; nominal ID 315.34 mm (API 5CT)"),
              std::string::npos)
        << given.output;
    const CommandRun header = runCaliper3d("info " + las.string());
    EXPECT_NE(header.output.find("in casing: to 20.00 m, median mean diameter 200.0 mm over 21 "
                                 "rows, nominal ID 201.2 mm, offset -1.2 mm"),
              std::string::npos)
        << header.output;
    const CommandRun info = runCaliper3d("info " + las.string() + " --casing 15,7in");
    EXPECT_NE(info.output.find("casing:    177.8 mm (7.000 in), shoe at 15.00 m; inner diameter "
                               "unknown (no weight) [--casing]"),
              std::string::npos)
        << info.output;
    EXPECT_EQ(runCaliper3d("info " + las.string() + " --casing 15,7in,17").status, 2);
}

// The north of azimuth curves and the declination, grid convergence and log date read
// from a LAS header (docs/formats.md, "North"); the real CMI log's remark.
#include "io/azimuth_north.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "io/curve_plan.h"
#include "io/las_header.h"
#include "test_support.h"

namespace caliper3d::io {
namespace {

TEST(AzimuthNorthTest, DescriptionPhrasesNameTheirNorth) {
    EXPECT_EQ(northFromText("PAD 1 AZIMUTH IN HORIZONTAL PLANE (0 = TRUE NORTH) {F14.5}"),
              North::True);
    EXPECT_EQ(northFromText("Borehole Azimuth (True)"), North::True);
    EXPECT_EQ(northFromText("HOLE AZIMUTH RELATIVE TO TRUE NORTH"), North::True);
    EXPECT_EQ(northFromText("azimuth corrected for magnetic declination"), North::True);
    EXPECT_EQ(northFromText("azimuth relative to magnetic north"), North::Magnetic);
    EXPECT_EQ(northFromText("Pad 1 azimuth (mag)"), North::Magnetic);
    EXPECT_EQ(northFromText("declination not applied"), North::Magnetic);
    EXPECT_EQ(northFromText("grid azimuth"), North::Grid);
    EXPECT_EQ(northFromText("Azimuth of Reference"), North::Unknown);
    EXPECT_EQ(northFromText("magnetic or true"), North::Unknown);  // names two: unknown
}

TEST(AzimuthNorthTest, DatesAsHeadersWriteThem) {
    // 23 February 2014: day 54 of 365, mid-day.
    const double feb23 = 2014.0 + 53.5 / 365.0;
    EXPECT_NEAR(parseLogYear("23-Feb-2014"), feb23, 1e-9);
    EXPECT_NEAR(parseLogYear("2014/02/23"), feb23, 1e-9);
    EXPECT_NEAR(parseLogYear("2014-02-23 09:08"), feb23, 1e-9);
    EXPECT_NEAR(parseLogYear("02/23/2014"), feb23, 1e-9);
    EXPECT_NEAR(parseLogYear("23/02/2014"), feb23, 1e-9);
    EXPECT_NEAR(parseLogYear("23-FEB-14"), feb23, 1e-9);
    EXPECT_NEAR(parseLogYear("16-JAN-2016 0830AM"), 2016.0 + 15.5 / 366.0, 1e-9);
    EXPECT_NEAR(parseLogYear("2022.07.02"), 2022.5, 1e-9);
    EXPECT_TRUE(std::isnan(parseLogYear("unknown")));
    EXPECT_TRUE(std::isnan(parseLogYear("31-Feb-2014")));
}

TEST(AzimuthNorthTest, EastPositiveAngles) {
    EXPECT_DOUBLE_EQ(parseEastAngle("14.38033"), 14.38033);
    EXPECT_DOUBLE_EQ(parseEastAngle("13.39  EAST"), 13.39);
    EXPECT_DOUBLE_EQ(parseEastAngle("5.2 W"), -5.2);
    EXPECT_DOUBLE_EQ(parseEastAngle("5.2W"), -5.2);
    EXPECT_DOUBLE_EQ(parseEastAngle("-3.1 deg"), -3.1);
    EXPECT_TRUE(std::isnan(parseEastAngle("N/A")));
}

TEST(AzimuthNorthTest, HeaderDeclinationConvergenceReferenceAndDate) {
    const std::string text =
        "~Version\nVERS. 2.0 :\nWRAP. NO :\n~Well\nDATE. 25-Jan-2018 : Logging Date\n"
        "~Curve\nDEPT.M : depth\nAZ1.DEG : pad 1 azimuth\nHAZ.DEG : hole azimuth\n"
        "~Parameter\nMAGDEC.DEG 7.5 W : magnetic declination\nGCONV.DEG 1.2 : grid convergence\n"
        "AZREF. GRID NORTH : azimuth reference\n~A\n";
    Diagnostics d;
    const LasHeader h = parseLasHeader(text, "hdr.las", &d);
    std::vector<ColumnSpec> columns = {
        {"DEPT", "M", "depth"}, {"AZ1", "DEG", "pad 1 azimuth"}, {"HAZ", "DEG", "hole azimuth"}};
    CurvePlan plan;
    plan.angleColumn[0] = 1;
    plan.angleColumn[2] = 2;
    const AzimuthNorth n = readAzimuthNorth(&h, columns, plan, &d);
    EXPECT_DOUBLE_EQ(n.declination.deg, -7.5);
    EXPECT_NE(n.declination.source.find("MAGDEC (~Parameter, line"), std::string::npos);
    EXPECT_DOUBLE_EQ(n.convergence.deg, 1.2);
    EXPECT_EQ(n.headerNorth, North::Grid);
    ASSERT_EQ(n.curves.size(), 2u);
    EXPECT_EQ(n.curves[0].north, North::Grid);  // from the header's AZREF
    EXPECT_FALSE(n.curves[0].stated);
    EXPECT_NEAR(n.logYear, 2018.0 + 24.5 / 365.0, 1e-9);
    EXPECT_EQ(d.warningCount, 0u);
}

TEST(AzimuthNorthTest, UnreadableDeclinationIsWarnedNotUsed) {
    const std::string text =
        "~Version\nVERS. 2.0 :\nWRAP. NO :\n~Well\n~Curve\nDEPT.M : depth\n"
        "~Parameter\nMDEC.DEG  N/A : magnetic declination\n~A\n";
    Diagnostics d;
    const LasHeader h = parseLasHeader(text, "hdr.las", &d);
    const AzimuthNorth n = readAzimuthNorth(&h, {{"DEPT", "M", "depth"}}, CurvePlan{}, &d);
    EXPECT_FALSE(n.declination.found());
    EXPECT_EQ(d.warningCount, 1u);
}

TEST(AzimuthNorthTest, RealCmiLogGivesItsDeclinationInARemark) {
    const auto file =
        test::sharedData() / "vendors" / "WL_0486896_AA-03-08-092-07W4-00_REPEAT_PASS DIPMETER.las";
    const auto moved =
        test::sharedData() / "real" / "WL_0486896_AA-03-08-092-07W4-00_REPEAT_PASS DIPMETER.las";
    const auto path = std::filesystem::exists(moved) ? moved : file;
    CALIPER3D_REQUIRE_DATA(path);
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    Diagnostics d;
    const LasHeader h = parseLasHeader(text.str(), path.string(), &d);
    const AzimuthNorth n = readAzimuthNorth(&h, {}, CurvePlan{}, &d);
    EXPECT_DOUBLE_EQ(n.declination.deg, 13.39);
    EXPECT_NE(n.declination.source.find("Magnetic Declanation: 13.39"), std::string::npos);
    EXPECT_NEAR(n.logYear, 2018.0 + 24.5 / 365.0, 1e-9);  // DATE 25-Jan-2018
    EXPECT_EQ(northFromText("Borehole Azimuth (True)"), North::True);
}

}  // namespace
}  // namespace caliper3d::io

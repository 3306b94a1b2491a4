// Image-log picks (docs/formats.md, "Picks"): LAS with a text type column, or delimited text.
#include "io/picks_reader.h"

#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "io/parse_error.h"
#include "test_support.h"

using namespace caliper3d::io;

namespace {
std::string write(const std::string& name, const std::string& text) {
    const std::string path = caliper3d::test::scratch(name).string();
    std::ofstream(path) << text;
    return path;
}
}  // namespace

TEST(PicksReaderTest, LasWithATextTypeColumn) {
    const std::string path =
        write("picks.las",
              "~Version\n VERS. 2.0 :\n WRAP. NO :\n~Well\n NULL. -999.25 :\n~Curve\n"
              " DEPT.FT : depth\n AZIM.DEG : breakout azimuth\n TYPE. : feature\n"
              "~A\n 1000.0 45.0 BREAKOUT\n 1010.0 -999.25 BREAKOUT\n 1020.5 140 DITF\n");
    const PickFile f = readPicks(path);
    ASSERT_EQ(f.picks.size(), 2u);
    EXPECT_NEAR(f.picks[0].top_m, 304.8, 1e-9);
    EXPECT_EQ(f.picks[0].bottom_m, f.picks[0].top_m);
    EXPECT_EQ(f.picks[0].azimuth_deg, 45.0);
    EXPECT_EQ(f.picks[0].type, "BREAKOUT");
    EXPECT_EQ(f.picks[1].type, "DITF");
    EXPECT_EQ(f.picks[1].line, 13u);
    // The null azimuth: skipped and counted, with its line.
    ASSERT_EQ(f.diagnostics.warningCount, 1u);
    EXPECT_EQ(f.diagnostics.warnings[0].line, 12u);
}

TEST(PicksReaderTest, DelimitedTextWithTopBottomAndUnits) {
    const std::string path = write("picks.csv",
                                   "# picked on the acoustic image\n"
                                   "top(m),bottom(m),azimuth(deg),type\n"
                                   "60.0,62.5,31,breakout\n"
                                   "70,69,211.5,\n"
                                   "x,71,10,breakout\n");
    const PickFile f = readPicks(path);
    ASSERT_EQ(f.picks.size(), 2u);
    EXPECT_EQ(f.picks[0].top_m, 60.0);
    EXPECT_EQ(f.picks[0].bottom_m, 62.5);
    EXPECT_EQ(f.picks[1].top_m, 69.0);  // written bottom first: put in order
    EXPECT_EQ(f.picks[1].azimuth_deg, 211.5);
    EXPECT_EQ(f.picks[1].type, "");
    EXPECT_EQ(f.diagnostics.warningCount, 1u);
}

TEST(PicksReaderTest, AFileWithoutAzimuthIsRefusedNamingTheLine) {
    const std::string path = write("no_azimuth.csv", "depth,type\n10,breakout\n");
    try {
        readPicks(path);
        FAIL() << "read a picks file without azimuths";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.file(), path);
        EXPECT_EQ(e.line(), 1u);
        EXPECT_NE(e.message().find("azimuth column"), std::string::npos);
    }
    EXPECT_THROW(readPicks(caliper3d::test::scratch("absent.csv").string()), ParseError);
}

TEST(PicksReaderTest, ABreakoutsTwoSidesAreOneDirection) {
    EXPECT_DOUBLE_EQ(axialDifference_deg(30.0, 210.0), 0.0);
    EXPECT_DOUBLE_EQ(axialDifference_deg(10.0, 170.0), 20.0);
    EXPECT_DOUBLE_EQ(axialDifference_deg(0.0, 90.0), 90.0);
    EXPECT_DOUBLE_EQ(axialDifference_deg(355.0, 5.0), 10.0);
}

#include "io/survey_reader.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "io/parse_error.h"
#include "test_support.h"

using namespace caliper3d::io;

TEST(SurveyReaderTest, ReadsPlainCsvWithUnitSuffixes) {
    const SurveyTable s =
        parseSurvey("MD_ft,INC_deg,AZI_deg,TVD_ft\n0,0,0,0\n100,10,45,99.5\n", "s.csv");
    ASSERT_EQ(s.stationCount(), 2u);
    EXPECT_EQ(s.depthUnit, LengthUnit::Foot);
    EXPECT_DOUBLE_EQ(s.md_m[1], 30.48);
    EXPECT_DOUBLE_EQ(s.inc_deg[1], 10.0);
    EXPECT_DOUBLE_EQ(s.azi_deg[1], 45.0);
    EXPECT_NEAR(s.tvd_m[1], 99.5 * 0.3048, 1e-12);
    EXPECT_TRUE(s.north_m.empty());
    EXPECT_EQ(s.headerLine, 1u);
}

TEST(SurveyReaderTest, SkipsReportPreambleUnitsLineAndFooter) {
    const std::string text =
        "Design Report\nMethod for positions.....: Minimum Curvature\n\n"
        "MD,Inc,Azim.,SSTVD,TVD,N/S,E/W,Y,X,DLS,V.S.,Comment\n"
        "(m),(Deg),(Deg),(m),(m),(m),(m),(m),(m),(dega/30m),(m)\n\n"
        "0.000,0.000,0.000,-593.700,0.000,0.000,0.000,1,2,0.000,0.000, \n"
        "9.200,1.500,10.000,-584.500,9.199,0.120,0.021,1,2,0.000,0.000,RKB to GL\n"
        "\nBased upon Minimum Curvature type calculations, at a Measured Depth of 9.20m.,\n";
    const SurveyTable s = parseSurvey(text, "report.csv");
    ASSERT_EQ(s.stationCount(), 2u);
    EXPECT_EQ(s.headerLine, 4u);
    EXPECT_DOUBLE_EQ(s.tvd_m[1], 9.199);  // TVD, not SSTVD
    EXPECT_DOUBLE_EQ(s.north_m[1], 0.120);
    EXPECT_DOUBLE_EQ(s.east_m[1], 0.021);
}

TEST(SurveyReaderTest, UnitsLineInFeetConvertsDepths) {
    const SurveyTable s = parseSurvey(
        "Measured Depth,Incl.,Azim.,Vertical Depth\n ft , , , ft\n0,0,0,0\n10,0,0,10\n", "f.csv");
    EXPECT_EQ(s.depthUnit, LengthUnit::Foot);
    EXPECT_DOUBLE_EQ(s.md_m[1], 3.048);
    EXPECT_DOUBLE_EQ(s.tvd_m[1], 3.048);
}

TEST(SurveyReaderTest, WhitespaceTableWithCommentsAndDecimalComma) {
    const SurveyTable s = parseSurvey(
        "# trace\n MD  X  TVD  INCL  AZIM_TN AZIM_GN\n0 5 0 0 0 359\n12,5 5 12,5 0,5 26,6 26,5\n",
        "t.txt");
    ASSERT_EQ(s.stationCount(), 2u);
    EXPECT_DOUBLE_EQ(s.md_m[1], 12.5);
    EXPECT_DOUBLE_EQ(s.inc_deg[1], 0.5);
    EXPECT_DOUBLE_EQ(s.azi_deg[1], 26.6);  // true north preferred over grid north
}

TEST(SurveyReaderTest, DepthUnitOptionOverridesTheFile) {
    SurveyReadOptions options;
    options.depthUnit = LengthUnit::Foot;
    const SurveyTable s = parseSurvey("MD_m,INC,AZI\n0,0,0\n10,0,0\n", "o.csv", options);
    EXPECT_DOUBLE_EQ(s.md_m[1], 3.048);
}

TEST(SurveyReaderTest, BadNumberNamesLineAndColumn) {
    try {
        parseSurvey("MD,INC,AZI\n0,0,0\n10,abc,0\n20,1,1\n", "bad.csv");
        FAIL() << "expected a ParseError";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.file(), "bad.csv");
        EXPECT_EQ(e.line(), 3u);
        EXPECT_EQ(e.column(), 4u);
        EXPECT_NE(std::string(e.what()).find("inclination"), std::string::npos);
    }
}

TEST(SurveyReaderTest, TextBetweenStationsIsAnError) {
    try {
        parseSurvey("MD,INC,AZI\n0,0,0\noops\n20,1,1\n", "mid.csv");
        FAIL() << "expected a ParseError";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 3u);
        EXPECT_EQ(e.column(), 1u);
    }
}

TEST(SurveyReaderTest, RejectsDecreasingDepthBadInclinationMissingHeaderAndShortTables) {
    EXPECT_THROW(parseSurvey("MD,INC,AZI\n10,0,0\n5,0,0\n", "d.csv"), ParseError);
    EXPECT_THROW(parseSurvey("MD,INC,AZI\n0,0,0\n5,181,0\n", "i.csv"), ParseError);
    EXPECT_THROW(parseSurvey("depth,gamma\n0,1\n5,2\n", "h.csv"), ParseError);
    EXPECT_THROW(parseSurvey("MD,INC,AZI\n0,0,0\n", "one.csv"), ParseError);
    EXPECT_THROW(parseSurvey("MD,INC,AZI\n0,0\n5,1,1\n", "short.csv"), ParseError);
    EXPECT_THROW(readSurvey("/nonexistent/survey.csv"), ParseError);
}

TEST(SurveyReaderTest, ReadsEveryPublishedSurveyLayout) {
    const auto dir = caliper3d::test::sharedData() / "surveys";
    CALIPER3D_REQUIRE_DATA(dir);
    struct Expect {
        const char* file;
        std::size_t stations;
        LengthUnit unit;
        bool hasNorth;
    };
    const Expect files[] = {
        {"iscwsa1_wellpath_extracted.csv", 268, LengthUnit::Metre, false},
        {"iscwsa2_wellpath_extracted.csv", 131, LengthUnit::Foot, false},
        {"DS_0490457_02-08-31-094-05W4-00_Final_Survey.csv", 0, LengthUnit::Metre, true},
        {"DS_0492236_AA-03-04-085-09W4-00_Final_Survey_Slant.csv", 0, LengthUnit::Metre, true},
        {"105030309506W400_DS_0484034.csv", 0, LengthUnit::Metre, true},
        {"well9.csv", 121, LengthUnit::Foot, true},
        {"100042209506W400.txt", 0, LengthUnit::Metre, true},
    };
    for (const Expect& e : files) {
        SCOPED_TRACE(e.file);
        const SurveyTable s = readSurvey((dir / e.file).string());
        if (e.stations) {
            EXPECT_EQ(s.stationCount(), e.stations);
        }
        EXPECT_GT(s.stationCount(), 20u);
        EXPECT_EQ(s.depthUnit, e.unit);
        EXPECT_EQ(s.tvd_m.size(), s.stationCount());
        EXPECT_EQ(!s.north_m.empty(), e.hasNorth);
    }
}

TEST(SurveyReaderTest, AWellColumnGivesOneWellTheFirstOrTheOneAskedFor) {
    const std::string text =
        "well,MD_m,INC_deg,AZI_deg\nA,0,0,0\nA,30,1,10\nB well,0,0,0\nB well,30,2,20\nB "
        "well,60,4,22\nA,60,2,12\n";
    Diagnostics diagnostics;
    const SurveyTable a = parseSurvey(text, "wells.csv", {}, &diagnostics);
    EXPECT_EQ(a.wellName, "A");
    EXPECT_EQ(a.wellCount, 2u);
    EXPECT_EQ(a.md_m, (std::vector<double>{0, 30, 60}));
    ASSERT_EQ(diagnostics.warningCount, 1u);
    EXPECT_NE(diagnostics.warnings[0].message.find(
                  "holds 2 wells in column 'well'; read 'A' (3 stations), 3 stations"),
              std::string::npos)
        << diagnostics.warnings[0].message;
    SurveyReadOptions options;
    options.well = "B well";
    const SurveyTable b = parseSurvey(text, "wells.csv", options);
    EXPECT_EQ(b.inc_deg, (std::vector<double>{0, 2, 4}));
    options.well = "C";
    try {
        parseSurvey(text, "wells.csv", options);
        FAIL() << "an absent well must be refused";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 1u);
        EXPECT_EQ(e.column(), 1u);
        EXPECT_NE(std::string(e.what()).find(
                      "expected stations of well 'C' in column 'well', found only 'A', 'B well'"),
                  std::string::npos)
            << e.what();
    }
}

TEST(SurveyReaderTest, ColumnsAreListedWithTheirRolesAndAGridAzimuthIsWarnedAbout) {
    Diagnostics diagnostics;
    const SurveyTable s = parseSurvey(
        "Measured Depth ( ft ),Inclination,Azimuth Grid ( deg ),DLS\n0,0,0,0\n10,1,2,3\n",
        "grid.csv", {}, &diagnostics);
    ASSERT_EQ(s.columns.size(), 4u);
    EXPECT_EQ(s.columns[0].name, "Measured Depth ( ft )");
    EXPECT_EQ(s.columns[0].role, "measured depth");
    EXPECT_EQ(s.columns[0].unit, "ft");
    EXPECT_EQ(s.columns[2].role, "azimuth");
    EXPECT_EQ(s.columns[3].role, "");
    ASSERT_EQ(diagnostics.warningCount, 1u);
    EXPECT_NE(diagnostics.warnings[0].message.find("grid-north column 'Azimuth Grid ( deg )'"),
              std::string::npos);
}

TEST(SurveyReaderTest, ErrorsSayWhatWasExpectedAndWhatWasFound) {
    auto message = [](const std::string& text) {
        try {
            parseSurvey(text, "e.csv");
        } catch (const ParseError& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    EXPECT_EQ(message("MD,INC,AZI\n10,0,0\n5,0,0\n"),
              "e.csv:3:1: expected measured depths that do not decrease (at least the 10 of the "
              "station before), "
              "found 5");
    EXPECT_EQ(message("MD,INC,AZI\n0,0,0\n5,181,0\n"),
              "e.csv:3:3: expected an inclination between 0 and 180 degrees, found 181");
    EXPECT_EQ(message("MD,INC,AZI\n0,0,0\nx,1,1\n20,1,1\n"),
              "e.csv:3:1: expected a number (measured depth), found 'x'");
    EXPECT_EQ(message("depth,gamma\n0,1\n"),
              "e.csv: expected a survey header, a line naming measured depth, inclination and "
              "azimuth columns "
              "(e.g. MD,INC,AZI), found none in 2 lines");
}

TEST(SurveyReaderTest, ASurveyIsToldFromACaliperLog) {
    EXPECT_TRUE(looksLikeSurvey("# trace\n MD  X  TVD  INCL  AZIM_TN\n0 5 0 0 0\n"));
    EXPECT_TRUE(
        looksLikeSurvey("Report\nClient: X\n\nMD,Inc,Azim.,TVD\n(m),(Deg),(Deg),(m)\n0,0,0,0\n"));
    EXPECT_FALSE(looksLikeSurvey(
        "DEPTH R1 R2 R3 R4 R5 R6 P1AZ DEVI HAZI\n1 2 2 2 2 2 2 0 0 0\n"));  // caliper names
    EXPECT_FALSE(looksLikeSurvey("1 2 3\nMD INC AZI\n"));                   // numbers first
    EXPECT_FALSE(looksLikeSurvey(
        "~Version\n VERS. 2.0 :\n~Curve\n MD.M :\n INC.DEG :\n AZI.DEG :\n"));  // LAS
    EXPECT_FALSE(looksLikeSurvey("depth,gamma\n0,1\n"));
}

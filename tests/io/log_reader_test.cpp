#include "io/log_reader.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include <gtest/gtest.h>

#include "io/parse_error.h"
#include "test_support.h"

using namespace caliper3d::io;

namespace {
bool warned(const LogInfo& info, const std::string& text) {
    for (const Warning& w : info.diagnostics.warnings)
        if (w.message.find(text) != std::string::npos) return true;
    return false;
}

// A 4-arm LAS in feet, inches and radians, two rows recorded upwards.
const char kFeetInchesRadians[] =
    "~Version\n VERS. 2.0 :\n WRAP. NO :\n~Well\n WELL. TEST-1 : name\n NULL. -999.25 :\n"
    "~Parameter\n BS.IN 8.5 : bit size\n"
    "~Curve\n DEPT.FT : depth\n R1.IN :\n R2.IN :\n R3.IN :\n R4.IN :\n P1AZ.RAD :\n DEVI.DEG :\n "
    "GR.GAPI :\n"
    "~A\n1001.0 4 4.5 4 4.5 3.14159265358979 2 80\n1000.0 4.25 4.25 4.25 -999.25 0 1 75\n";
}  // namespace

TEST(LogReaderTest, LasUnitsAreConvertedOnceToMetresMillimetresAndDegrees) {
    const LoadedLog log = loadCaliperText(kFeetInchesRadians, "u.las", ReadOptions{});
    const SectionTable& t = log.table;
    ASSERT_EQ(t.rowCount(), 2u);
    ASSERT_EQ(t.armCount, 4);
    EXPECT_DOUBLE_EQ(t.depth_m[0], 1000.0 * 0.3048);  // sorted: the upward log is reversed
    EXPECT_DOUBLE_EQ(t.depth_m[1], 1001.0 * 0.3048);
    EXPECT_DOUBLE_EQ(t.radii(1)[1], 4.5 * 25.4);
    EXPECT_TRUE(std::isnan(t.radii(0)[3]));
    EXPECT_NEAR(t.p1az_deg[1], 180.0, 1e-9);
    EXPECT_DOUBLE_EQ(t.devi_deg[0], 1.0);
    ASSERT_EQ(t.bitSize_mm.size(), 2u);
    EXPECT_DOUBLE_EQ(t.bitSize_mm[0], 8.5 * 25.4);
    ASSERT_EQ(t.extraCurves.size(), 1u);
    EXPECT_EQ(t.extraCurves[0].mnemonic, "GR");
    EXPECT_DOUBLE_EQ(t.extraCurves[0].values[0], 75.0);  // moved with its row
    EXPECT_EQ(log.info.wellName, "TEST-1");
    EXPECT_TRUE(warned(log.info, "log recorded upwards"));
}

TEST(LogReaderTest, OverridesChooseUnitsRadiiAndBitSize) {
    ReadOptions options;
    options.radiusUnit = LengthUnit::Millimetre;
    options.depthUnit = LengthUnit::Metre;
    options.bitSize_mm = 200.0;
    options.roles.radii = {"R4", "R3", "R2"};
    const LoadedLog log = loadCaliperText(kFeetInchesRadians, "o.las", options);
    ASSERT_EQ(log.table.armCount, 3);
    EXPECT_DOUBLE_EQ(log.table.depth_m[1], 1001.0);
    EXPECT_DOUBLE_EQ(log.table.radii(1)[0], 4.5);
    EXPECT_DOUBLE_EQ(log.table.bitSize_mm[0], 200.0);
    options.roles.radii = {"R1", "NOPE", "R2"};
    EXPECT_THROW(loadCaliperText(kFeetInchesRadians, "o.las", options), ParseError);
}

TEST(LogReaderTest, DiametersBecomeRadiiOfOppositePads) {
    const std::string text =
        "~V\n VERS. 2.0 :\n WRAP. NO :\n~C\n DEPT.M :\n C1.IN :\n C2.IN :\n~A\n10 8 10\n";
    const LoadedLog log = loadCaliperText(text, "c.las", ReadOptions{});
    ASSERT_EQ(log.table.armCount, 4);
    const double* r = log.table.radii(0);
    EXPECT_DOUBLE_EQ(r[0], 4 * 25.4);  // pad 1 and pad 3 share C1
    EXPECT_DOUBLE_EQ(r[1], 5 * 25.4);  // pad 2 and pad 4 share C2
    EXPECT_DOUBLE_EQ(r[2], 4 * 25.4);
    EXPECT_DOUBLE_EQ(r[3], 5 * 25.4);
    EXPECT_TRUE(warned(log.info, "opposite-pad diameters"));
}

TEST(LogReaderTest, RepeatedDepthRowsAreSkippedAndCounted) {
    const std::string text =
        "1.0 1 1 1 1 1 1 0 0 0\n1.0 2 2 2 2 2 2 0 0 0\n1.1 3 3 3 3 3 3 0 0 0\n";
    const LoadedLog log = loadCaliperText(text, "r.txt", ReadOptions{});
    ASSERT_EQ(log.table.rowCount(), 2u);
    EXPECT_DOUBLE_EQ(log.table.radii(0)[0], 25.4);
    EXPECT_TRUE(warned(log.info, "1 rows repeat the depth"));
}

TEST(LogReaderTest, ColumnTextWithHeaderNamesIsDetectedAsText) {
    const std::string text = "DEPTH R1 R2 R3 R4 R5 R6 P1AZ DEVI HAZI\r\n1.0 4 4 4 4 4 4 0 0 0\r\n";
    const LoadedLog log = loadCaliperText(text, "h.txt", ReadOptions{});
    EXPECT_EQ(log.table.rowCount(), 1u);
    EXPECT_NE(log.info.format.find("column text"), std::string::npos);
}

TEST(LogReaderTest, InfoNamesFormatDepthRangeRolesAndNulls) {
    const LoadedLog log = loadCaliperText(kFeetInchesRadians, "u.las", ReadOptions{});
    const std::string out = formatLogInfo(log.info);
    for (const char* expected :
         {"LAS 2", "TEST-1", "rows:      2", "R1", "radius", "P1AZ", "pad-1 azimuth", ", 1 null\n",
          "GR", "other", "bit size:  215.9 mm", "(file unit FT)"})
        EXPECT_NE(out.find(expected), std::string::npos) << expected << "\n" << out;
}

TEST(LogReaderTest, ALogWithoutCaliperCurvesIsRefusedByReadCaliperLog) {
    const std::string path = ::testing::TempDir() + "/nocal.las";
    {
        FILE* f = std::fopen(path.c_str(), "wb");
        std::fputs("~V\n VERS. 2.0 :\n~C\n DEPT.M :\n GR.GAPI :\n~A\n1 2\n", f);
        std::fclose(f);
    }
    try {
        readCaliperLog(path, ReadOptions{}, nullptr);
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_NE(std::string(e.what()).find("expected caliper curves"), std::string::npos)
            << e.what();
    }
}

namespace {
// The message of the ParseError that `read` throws, or "(no error)".
template <typename Read>
std::string refusal(Read read) {
    try {
        read();
    } catch (const ParseError& e) {
        return e.what();
    }
    return "(no error)";
}

std::string writeScratch(const std::string& name, const std::string& text) {
    const auto path = caliper3d::test::scratch(name);
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
}
}  // namespace

TEST(LogReaderTest, ASurveyJsonOrBinaryFileIsRefusedAsACaliperLogWithWhatItIs) {
    // Eleven numbers per line would otherwise read as an 11-arm radii-only log.
    const std::string petrel =
        "# WELL TRACE FROM PETREL\n MD X Y Z TVD DX DY AZIM_TN INCL DLS AZIM_GN\n"
        "0 1 2 3 0 0 0 0 0 0 0\n10 1 2 3 10 0 0 5 1 0.1 4\n";
    EXPECT_NE(refusal([&] {
                  loadCaliperText(petrel, "trace.txt", ReadOptions{});
              }).find("found a deviation survey"),
              std::string::npos);
    EXPECT_NE(refusal([&] {
                  loadCaliperText("MD,INC,AZI\n0,0,0\n10,1,2\n", "s.csv", ReadOptions{});
              }).find("s.csv: expected a caliper log, found a deviation survey"),
              std::string::npos);
    EXPECT_NE(refusal([&] {
                  loadCaliperText("\n  {\"md\": [0, 10]}\n", "w.json", ReadOptions{});
              }).find("w.json:2: expected a caliper log (LAS or column text), found JSON"),
              std::string::npos);
    const std::string binary = std::string("1.0 2 2 2 2 2 2 0 0 0\n2.0 2 2\0 2", 30);
    EXPECT_NE(refusal([&] {
                  loadCaliperText(binary, "b.bin", ReadOptions{});
              }).find("b.bin:2:8: expected text, found a NUL byte"),
              std::string::npos);
    // A caliper text whose names line also names depth, deviation and azimuth is a log.
    const LoadedLog log = loadCaliperText(
        "DEPTH R1 R2 R3 R4 R5 R6 P1AZ DEVI HAZI\n1.0 4 4 4 4 4 4 0 0 0\n", "c.txt", ReadOptions{});
    EXPECT_EQ(log.table.rowCount(), 1u);
}

TEST(LogReaderTest, InfoDescribesASurveyWithItsStationsAndColumns) {
    const std::string path = writeScratch(
        "info_survey.csv",
        "Design "
        "Report\n\nMD,Inc,Azim.,TVD,N/S,E/W,DLS\n(ft),(Deg),(Deg),(ft),(ft),(ft),(dega/100ft)\n"
        "0,0,0,0,0,0,0\n100,1,10,99.99,0.86,0.15,1\n300,3,12,299.8,,,1\n\nEnd of report\n");
    const LogInfo info = describeLog(path, ReadOptions{});
    EXPECT_TRUE(info.survey);
    EXPECT_EQ(info.format, "deviation survey (comma-separated, column names on line 3)");
    EXPECT_EQ(info.rows, 3u);
    EXPECT_DOUBLE_EQ(info.bottom_m, 300 * 0.3048);
    EXPECT_NEAR(info.step_m, 200 * 0.3048,
                1e-9);  // median of 100 and 200 ft steps: the upper middle
    EXPECT_EQ(info.depthUnit, "ft");
    ASSERT_EQ(info.curves.size(), 7u);
    EXPECT_EQ(info.curves[0].role, "measured depth");
    EXPECT_EQ(info.curves[1].role, "inclination");
    EXPECT_EQ(info.curves[2].role, "azimuth");
    EXPECT_EQ(info.curves[3].role, "TVD (read for checking)");
    EXPECT_EQ(info.curves[4].role, "north (read for checking)");
    EXPECT_EQ(info.curves[4].nulls, 1u);
    EXPECT_EQ(info.curves[6].role, "not read");
    EXPECT_TRUE(warned(info, "1 lines of text after the last station skipped"));
    const std::string text = formatLogInfo(info);
    EXPECT_NE(text.find("rows:      3 stations\n"), std::string::npos) << text;
    EXPECT_NE(text.find("MD:        0.0000 to 91.4400 m"), std::string::npos) << text;
    EXPECT_EQ(text.find("bit size"), std::string::npos) << text;
}

// What `caliper3d info` does with every file of the reference data: describe
// it, or refuse it with a precise message naming why.
TEST(LogReaderTest, InfoDescribesEveryReferenceFileOrSaysWhyNot) {
    const auto root = caliper3d::test::sharedData();
    CALIPER3D_REQUIRE_DATA(root / "las_edge_cases");
    const std::map<std::string, std::string> refused = {
        {"missing_a_section.las", ":20: expected data rows after ~A, found none"},
        {"missing_well_curves_ascii_section.las",
         ": expected a ~C (curve information) section, found none"},
        {"clearance_iscwsa_well_data.json",
         ":1: expected a caliper log (LAS or column text), found JSON"},
        {"error_mwdrev5_1_iscwsa_data.json",
         ":1: expected a caliper log (LAS or column text), found JSON"},
    };
    const std::map<std::string, std::string> formats = {
        {"1AA072209208W400_WL_0477502_STAR_FIELD.las", "LAS 2.0"},
        {"1AA063409108W400_FMI_SONIC_MAIN.las", "LAS 2.0"},
        {"multifinger40_data.txt", "column text (40 radii per line, no depth)"},
        {"sample_3.0.las", "LAS 3.0"},
        {"sample_wrapped.las", "LAS 1.2, wrapped"},
        {"100042209506W400.txt",
         "deviation survey (columns separated by spaces, column names on line 16)"},
        {"iscwsa_clearance_wells_extracted.csv",
         "deviation survey (comma-separated, column names on line 2)"},
        {"well9.csv", "deviation survey (comma-separated, column names on line 1)"},
    };
    int files = 0, surveys = 0;
    for (const char* folder : {"las_edge_cases", "real", "surveys"}) {
        for (const auto& entry : std::filesystem::directory_iterator(root / folder)) {
            const std::string name = entry.path().filename().string();
            SCOPED_TRACE(name);
            ++files;
            const auto refusedIt = refused.find(name);
            if (refusedIt != refused.end()) {
                EXPECT_NE(refusal([&] {
                              describeLog(entry.path().string(), ReadOptions{});
                          }).find(entry.path().string() + refusedIt->second),
                          std::string::npos);
                continue;
            }
            const LogInfo info = describeLog(entry.path().string(), ReadOptions{});
            EXPECT_GT(info.rows, 1u);
            EXPECT_FALSE(info.curves.empty());
            EXPECT_EQ(info.survey, std::string(folder) == "surveys");
            surveys += info.survey;
            if (formats.count(name)) {
                EXPECT_EQ(info.format, formats.at(name));
            }
            EXPECT_FALSE(formatLogInfo(info).empty());
        }
    }
    EXPECT_EQ(files, 22 + 3 + 10);
    EXPECT_EQ(surveys, 8);
}

namespace {
// LAS 3.0, comma-delimited: an 8-finger caliper stored as one array channel,
// a string column (blanks inside, and a quoted comma) and a gamma ray.
std::string las3Array(const std::string& array) {
    std::string text =
        "~Version\n VERS. 3.0 : CWLS LAS 3.0\n WRAP. NO :\n DLM. COMMA : delimiter\n"
        "~Well\n WELL. ARRAY-1 : well\n NULL. -999.25 :\n~Log_Parameter\n BS.MM 215.9 : bit size "
        "{F}\n"
        "~Log_Definition\n DEPT.M : depth {F}\n";
    for (int k = 1; k <= 8; ++k)
        text += " " + array + "[" + std::to_string(k) + "].IN : finger radius {AF}\n";
    text += " LITH. : lithology {S}\n GR.GAPI : gamma ray {F}\n~Log_Data | Log_Definition\n";
    for (int r = 0; r < 3; ++r) {
        text += std::to_string(100.0 + 0.1 * r);
        for (int k = 1; k <= 8; ++k) text += "," + std::to_string(4.0 + 0.125 * k + r);
        text += r == 1 ? ", \"SAND, SHALY\" ,-999.25\n" : ",SAND WITH SHELLS,55.5\n";
    }
    return text;
}
}  // namespace

TEST(LogReaderTest, Las3FingerArrayIsTheArmsAndStringColumnIsSkippedWithANote) {
    const LoadedLog log = loadCaliperText(las3Array("FING"), "array.las", ReadOptions{});
    ASSERT_EQ(log.table.armCount, 8);
    ASSERT_EQ(log.table.rowCount(), 3u);
    EXPECT_DOUBLE_EQ(log.table.radii(1)[0], (4.125 + 1) * 25.4);
    EXPECT_DOUBLE_EQ(log.table.radii(2)[7], (5.0 + 2) * 25.4);
    EXPECT_DOUBLE_EQ(log.table.bitSize_mm[0], 215.9);
    ASSERT_EQ(log.table.extraCurves.size(), 1u);  // GR; LITH is text
    EXPECT_DOUBLE_EQ(log.table.extraCurves[0].values[0], 55.5);
    EXPECT_TRUE(std::isnan(log.table.extraCurves[0].values[1]));
    EXPECT_TRUE(warned(log.info, "curve 'LITH' holds text; skipped"));
    EXPECT_EQ(log.info.curves[1].role, "finger radius");
    EXPECT_EQ(log.info.curves[9].role, "text (skipped)");
}

TEST(LogReaderTest, AnArrayWithAnUnknownNameIsNamedWithBrackets) {
    const std::string text = las3Array("MFC");
    EXPECT_EQ(loadCaliperText(text, "mfc.las", ReadOptions{}).table.armCount, 0);
    ReadOptions options;
    options.roles.radii = {"MFC[]"};
    const LoadedLog log = loadCaliperText(text, "mfc.las", options);
    ASSERT_EQ(log.table.armCount, 8);
    EXPECT_DOUBLE_EQ(log.table.radii(0)[3], 4.5 * 25.4);
}

TEST(LogReaderTest, AnUnclosedQuoteInAStringColumnIsAnErrorAtItsColumn) {
    std::string text = las3Array("FING");
    text.replace(text.find("\"SAND, SHALY\""), 13, "\"SAND, SHALY");
    const std::string message = refusal([&] { loadCaliperText(text, "q.las", ReadOptions{}); });
    EXPECT_NE(message.find("q.las:24:85: "), std::string::npos)
        << message;  // the second data row, at the quote
    EXPECT_NE(message.find(
                  "expected a closing '\"' for the text of curve LITH, found the end of the line"),
              std::string::npos)
        << message;
}

namespace {
std::string utf16(const std::string& ascii, bool bigEndian) {
    std::string out = bigEndian ? std::string("\xFE\xFF", 2) : std::string("\xFF\xFE", 2);
    for (char c : ascii) {
        out.push_back(bigEndian ? '\0' : c);
        out.push_back(bigEndian ? c : '\0');
    }
    return out;
}
}  // namespace

TEST(LogReaderTest, Utf16WithAByteOrderMarkIsDecodedEitherWayAndABrokenOneRefusedAtItsLine) {
    for (bool bigEndian : {false, true}) {
        SCOPED_TRACE(bigEndian ? "big-endian" : "little-endian");
        const LoadedLog log =
            loadCaliperText(utf16(kFeetInchesRadians, bigEndian), "u16.las", ReadOptions{});
        EXPECT_EQ(log.table.rowCount(), 2u);
        EXPECT_EQ(log.table.armCount, 4);
        EXPECT_TRUE(warned(log.info, "text is UTF-16; decoded"));
    }
    std::string broken = utf16("~Version\n VERS. 2.0 :\n", false);
    broken += std::string("\x00\xD8", 2);  // a high surrogate with no low one, on line 3
    EXPECT_NE(refusal([&] {
                  loadCaliperText(broken, "bad16.las", ReadOptions{});
              }).find("bad16.las:3: expected UTF-16 text, found an unpaired surrogate"),
              std::string::npos);
}

TEST(LogReaderTest, ColumnTextNamesChooseRolesAndUnitsInAnyOrder) {
    // Names with units in brackets or after '_'; columns in any order; GR kept.
    const std::string text =
        "DEPTH[ft] GR HAZI_deg DEVI_deg R1(mm) R2(mm) R3(mm) R4(mm) P1AZ_rad\n"
        "1000 55 90 2 100 101 102 103 0\n"
        "1000.5 56 90 2 110 111 112 113 3.14159265358979\n";
    const LoadedLog log = loadCaliperText(text, "named.txt", ReadOptions{});
    ASSERT_EQ(log.table.rowCount(), 2u);
    EXPECT_EQ(log.table.armCount, 4);
    EXPECT_DOUBLE_EQ(log.table.depth_m[1], 1000.5 * 0.3048);
    EXPECT_DOUBLE_EQ(log.table.radii(1)[3], 113.0);
    EXPECT_NEAR(log.table.p1az_deg[1], 180.0, 1e-9);
    EXPECT_DOUBLE_EQ(log.table.hazi_deg[0], 90.0);
    ASSERT_EQ(log.table.extraCurves.size(), 1u);
    EXPECT_EQ(log.table.extraCurves[0].mnemonic, "GR");
    EXPECT_EQ(log.table.extraCurves[0].values, (std::vector<double>{55.0, 56.0}));
    EXPECT_EQ(log.info.format, "column text (9 named columns, names on line 1)");
}

TEST(LogReaderTest, ColumnTextNamesWithoutUnitsTakeTheTextDefaultsAndSaySo) {
    // Ten columns, and the names say that three of them are not radii: without
    // names this line would read as six radii (P1AZ, DEVI, HAZI as R4..R6).
    const std::string text =
        "# a comment\n"
        "DEPTH R1 R2 R3 P1AZ DEVI HAZI RB BS GR\n"
        "100 4 4 4 10 1 20 0 8.5 70\n";
    const LoadedLog log = loadCaliperText(text, "units.txt", ReadOptions{});
    EXPECT_EQ(log.table.armCount, 3);
    EXPECT_DOUBLE_EQ(log.table.radii(0)[2], 4.0 * 25.4);  // inches, the text default
    EXPECT_DOUBLE_EQ(log.table.bitSize_mm[0], 8.5 * 25.4);
    EXPECT_DOUBLE_EQ(log.table.rb_deg[0], 0.0);
    EXPECT_EQ(log.info.curves[1].unit, "in (assumed)");
    EXPECT_NE(formatLogInfo(log.info).find("R1           in (assumed) radius"), std::string::npos)
        << formatLogInfo(log.info);
}

TEST(LogReaderTest, ColumnTextCommentNamesCountOnlyWhenTheyFitTheData) {
    // A '#' line of names right before the data, starting with a depth: used.
    const LoadedLog named =
        loadCaliperText("# depth_m R1_mm R2_mm R3_mm\n1 100 100 100\n", "c.txt", ReadOptions{});
    EXPECT_EQ(named.table.armCount, 3);
    EXPECT_DOUBLE_EQ(named.table.radii(0)[0], 100.0);
    // A plain comment is a comment: the reference layout (6 arms) reads the row.
    const LoadedLog plain =
        loadCaliperText("# logged 2024\n1 4 4 4 4 4 4 0 0 0\n", "p.txt", ReadOptions{});
    EXPECT_EQ(plain.table.armCount, 6);
    // Names that do not fit the columns are ignored with a warning naming their line.
    const LoadedLog misfit =
        loadCaliperText("\nDEPTH R1 R2\n1 4 4 4 4 4 4 0 0 0\n", "m.txt", ReadOptions{});
    EXPECT_EQ(misfit.table.armCount, 6);
    EXPECT_TRUE(warned(misfit.info, "3 column names over 10 columns of numbers"));
    EXPECT_EQ(misfit.info.diagnostics.warnings.at(0).line, 2u);
}

TEST(LogReaderTest, TwoPadToolsReadAsTwoArmsFromOneDiameterOrTwoRadii) {
    // One diameter (CALI, the density tool's caliper; or C1 alone): pads 1 and 2, each half of it.
    for (const char* name : {"CALI", "C1", "HCAL"}) {
        SCOPED_TRACE(name);
        const std::string text =
            std::string("~V\n VERS. 2.0 :\n WRAP. NO :\n~C\n DEPT.M :\n GR.GAPI :\n ") + name +
            ".IN :\n~A\n10 50 8.5\n10.5 55 9\n";
        const LoadedLog log = loadCaliperText(text, "one.las", ReadOptions{});
        ASSERT_EQ(log.table.armCount, 2);
        EXPECT_DOUBLE_EQ(log.table.radii(1)[0], 4.5 * 25.4);
        EXPECT_DOUBLE_EQ(log.table.radii(1)[1], 4.5 * 25.4);
        EXPECT_TRUE(warned(log.info, "two pads measure one diameter"));
        EXPECT_EQ(log.table.extraCurves.size(), 1u);  // GR kept
    }
    // Two named radii in column text.
    const LoadedLog two =
        loadCaliperText("depth_m R1_mm R2_mm\n1 110 90\n2 111 91\n", "two.txt", ReadOptions{});
    ASSERT_EQ(two.table.armCount, 2);
    EXPECT_DOUBLE_EQ(two.table.radii(1)[1], 91.0);
    // A single radius is no section: not taken as a caliper, and refused naming the curve when
    // asked for.
    EXPECT_EQ(loadCaliperText("depth_m R1_mm\n1 110\n", "r1.txt", ReadOptions{}).table.armCount, 0);
    ReadOptions one;
    one.roles.radii = {"R1"};
    EXPECT_NE(refusal([&] {
                  loadCaliperText("depth_m R1_mm\n1 110\n", "r1.txt", one);
              }).find("expected at least 2 arm radii (or one diameter), found 1: R1"),
              std::string::npos);
}

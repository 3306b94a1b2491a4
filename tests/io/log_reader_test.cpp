#include "io/log_reader.h"

#include <cmath>

#include <gtest/gtest.h>

#include "io/parse_error.h"

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
    "~Curve\n DEPT.FT : depth\n R1.IN :\n R2.IN :\n R3.IN :\n R4.IN :\n P1AZ.RAD :\n DEVI.DEG :\n GR.GAPI :\n"
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
    const std::string text = "1.0 1 1 1 1 1 1 0 0 0\n1.0 2 2 2 2 2 2 0 0 0\n1.1 3 3 3 3 3 3 0 0 0\n";
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
    for (const char* expected : {"LAS 2", "TEST-1", "rows:      2", "R1", "radius", "P1AZ", "pad-1 azimuth",
                                 "1 nulls", "GR", "other", "bit size:  215.9 mm", "(file unit FT)"})
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
        EXPECT_NE(std::string(e.what()).find("expected caliper curves"), std::string::npos) << e.what();
    }
}

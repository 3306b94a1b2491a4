#include "support/column_text_reader.h"

#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "io/column_text_writer.h"
#include "io/parse_error.h"

using namespace caliper3d::io;

TEST(ColumnTextReaderTest, ReadsReferenceLayoutWithTabsAndDecimalComma) {
    const std::string text =
        "1000.0\t4.25 4.25 4.25 4.25 4.25 4.25 359.97920 0.5 10\r\n"
        "\n"
        "# a comment\n"
        "1000,0025 4,30 4,20 4,25 4,25 4,25 4,25 359,98610 0,5 10\n";
    SectionTable t = parseColumnText(text, "well.txt", ColumnTextOptions{});
    ASSERT_EQ(t.rowCount(), 2u);
    EXPECT_EQ(t.armCount, 6);
    EXPECT_DOUBLE_EQ(t.depth_m[1], 1000.0025);
    EXPECT_NEAR(t.radii(0)[0], 4.25 * 25.4, 1e-9);  // inches -> mm
    EXPECT_NEAR(t.radii(1)[1], 4.20 * 25.4, 1e-9);
    EXPECT_DOUBLE_EQ(t.p1az_deg[0], 359.9792);
    EXPECT_DOUBLE_EQ(t.p1az_deg[1], 359.9861);
    EXPECT_DOUBLE_EQ(t.devi_deg[1], 0.5);
    EXPECT_DOUBLE_EQ(t.hazi_deg[1], 10.0);
}

TEST(ColumnTextReaderTest, WrongColumnCountNamesFileLineAndLayout) {
    // (A short last line is a truncated row: skipped with a warning. One in the middle is not.)
    const std::string text = "1 2 3 4 5 6 7 8 9 10\n1 2 3 4 5 6 7 8 9\n3 2 3 4 5 6 7 8 9 10\n";
    try {
        parseColumnText(text, "bad.txt", ColumnTextOptions{});
        FAIL() << "expected a ParseError";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.file(), "bad.txt");
        EXPECT_EQ(e.line(), 2u);
        EXPECT_NE(std::string(e.what()).find("expected 10 columns"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("found 9"), std::string::npos) << e.what();
    }
}

TEST(ColumnTextReaderTest, NonNumberNamesColumnAndToken) {
    const std::string text = "1 2 3 x3 4 5 6 7 8 9\n";
    try {
        parseColumnText(text, "bad.txt", ColumnTextOptions{});
        FAIL() << "expected a ParseError";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 1u);
        EXPECT_EQ(e.column(), 7u);
        EXPECT_NE(std::string(e.what()).find("R3"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("'x3'"), std::string::npos) << e.what();
    }
}

TEST(ColumnTextReaderTest, ArmCountAndUnitsAreOptions) {
    ColumnTextOptions options;
    options.armCount = 4;
    options.radiusUnit = LengthUnit::Millimetre;
    options.depthUnit = LengthUnit::Foot;
    SectionTable t = parseColumnText("100 101 102 103 104 5 6 7\n", "f.txt", options);
    ASSERT_EQ(t.rowCount(), 1u);
    EXPECT_DOUBLE_EQ(t.depth_m[0], 30.48);
    EXPECT_DOUBLE_EQ(t.radii(0)[3], 104.0);
}

TEST(ColumnTextReaderTest, WriterOutputReadsBack) {
    SectionTable t;
    t.armCount = 6;
    for (int i = 0; i < 5; ++i) {
        t.depth_m.push_back(100.0 + 0.0025 * i);
        for (int k = 0; k < 6; ++k) t.radius_mm.push_back(108.0 + i + 0.1 * k);
        t.p1az_deg.push_back(12.5 * i);
        t.devi_deg.push_back(1.0);
        t.hazi_deg.push_back(200.0);
    }
    std::ostringstream out;
    writeColumnText(out, t);
    SectionTable back = parseColumnText(out.str(), "roundtrip", ColumnTextOptions{});
    ASSERT_EQ(back.rowCount(), t.rowCount());
    for (std::size_t i = 0; i < t.radius_mm.size(); ++i)
        EXPECT_NEAR(back.radius_mm[i], t.radius_mm[i], 1e-9);
    EXPECT_EQ(back.depth_m, t.depth_m);
    EXPECT_EQ(back.p1az_deg, t.p1az_deg);
}

TEST(ColumnTextReaderTest, NamesLineIsSkippedAndRadiiOnlyRowsGetSynthesisedDepth) {
    const std::string named = "DEPTH R1 R2 R3 R4 R5 R6 P1AZ DEVI HAZI\r\n1.0 4 4 4 4 4 4 0 0 0\r\n";
    EXPECT_EQ(parseColumnText(named, "n.txt", ColumnTextOptions{}).rowCount(), 1u);

    const std::string radii =
        "\xEF\xBB\xBF"
        "1 2 3 4 5 6 7 8\n2 3 4 5 6 7 8 9\n";
    ColumnTextOptions options;
    options.radiusUnit = LengthUnit::Millimetre;
    options.rowStep_m = 0.5;
    Diagnostics d;
    const SectionTable t = parseColumnText(radii, "r.txt", options, &d);
    EXPECT_EQ(t.armCount, 8);
    EXPECT_EQ(t.depth_m, (std::vector<double>{0.0, 0.5}));
    EXPECT_DOUBLE_EQ(t.radii(1)[7], 9.0);
    EXPECT_EQ(d.warningCount, 1u);

    options.allowRadiiOnly = false;
    EXPECT_THROW(parseColumnText(radii, "r.txt", options), ParseError);
}

TEST(ColumnTextReaderTest, WriterKeepsEveryCurveAndLeavesOutMissingOnes) {
    SectionTable t;
    t.armCount = 4;
    for (int i = 0; i < 3; ++i) {
        t.depth_m.push_back(50.0 + 0.5 * i);
        for (int k = 0; k < 4; ++k) t.radius_mm.push_back(100.0 + i + 0.25 * k);
        t.devi_deg.push_back(10.0 + i);
        t.hazi_deg.push_back(270.0);
        t.rb_deg.push_back(30.0 * i);
        t.bitSize_mm.push_back(215.9);
    }
    t.radius_mm[5] = kNaN;  // a null reading stays null
    t.extraCurves.push_back({"GR", "gAPI", "gamma ray", {40.0, 41.5, kNaN}});
    std::ostringstream out;
    writeColumnText(out, t, LengthUnit::Millimetre);
    EXPECT_EQ(
        out.str().substr(0, out.str().find('\n')),
        "depth_m R1_mm R2_mm R3_mm R4_mm DEVI_deg HAZI_deg RB_deg BS_mm GR[gAPI]");  // no P1AZ
                                                                                     // column
    const SectionTable back = parseColumnText(out.str(), "back.txt", ColumnTextOptions{});
    ASSERT_EQ(back.armCount, 4);
    EXPECT_EQ(back.depth_m, t.depth_m);
    for (std::size_t i = 0; i < t.radius_mm.size(); ++i) {
        if (std::isnan(t.radius_mm[i]))
            EXPECT_TRUE(std::isnan(back.radius_mm[i])) << i;
        else
            EXPECT_DOUBLE_EQ(back.radius_mm[i], t.radius_mm[i]) << i;
    }
    EXPECT_TRUE(back.p1az_deg.empty());  // never zeros for a curve the table lacks
    EXPECT_EQ(back.devi_deg, t.devi_deg);
    EXPECT_EQ(back.rb_deg, t.rb_deg);
    EXPECT_EQ(back.bitSize_mm, t.bitSize_mm);
    ASSERT_EQ(back.extraCurves.size(), 1u);
    EXPECT_EQ(back.extraCurves[0].mnemonic, "GR");
    EXPECT_EQ(back.extraCurves[0].unit, "gAPI");
    EXPECT_EQ(back.extraCurves[0].values[1], 41.5);
    EXPECT_TRUE(std::isnan(back.extraCurves[0].values[2]));
}

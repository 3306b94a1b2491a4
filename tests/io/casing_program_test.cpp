// The casing program from the LAS header and from --casing, and the API 5CT inner diameter
// (docs/analysis.md, "Cased hole"; docs/formats.md, "Casing program").
#include "io/casing_program.h"

#include <cmath>

#include <gtest/gtest.h>

#include "io/log_reader.h"
#include "test_support.h"

using namespace caliper3d::io;

namespace {

LasHeader headerWith(const std::string& parameters) {
    const std::string text =
        "~Version\n VERS. 2.0 :\n WRAP. NO :\n~Well\n STRT.M 10 :\n~Parameter\n" + parameters +
        "~Curve\n DEPT.M :\n R1.IN :\n R2.IN :\n R3.IN :\n~A\n1 4 4 4\n";
    return parseLasHeader(text, "h.las", nullptr);
}

}  // namespace

TEST(CasingProgramTest, ApiNominalWallGivesTheInnerDiameter) {
    // 7 in 17 lb/ft: wall 0.231 in, ID 6.538 in = 166.07 mm (API 5CT casing list).
    EXPECT_NEAR(nominalCasingId_mm(177.8, 25.3), 6.538 * 25.4, 1e-9);
    EXPECT_NEAR(nominalCasingId_mm(177.8, 17.0 * 1.48816394), 166.0652, 1e-3);
    // 9 5/8 in 47 lb/ft: wall 0.472 in, ID 8.681 in.
    EXPECT_NEAR(nominalCasingId_mm(244.475, 47.0 * 1.48816394), 8.681 * 25.4, 1e-9);
    // Not in the table: unknown, never guessed.
    EXPECT_TRUE(std::isnan(nominalCasingId_mm(177.8, 28.0)));  // 18.8 lb/ft
    EXPECT_TRUE(std::isnan(nominalCasingId_mm(180.0, 25.3)));
    EXPECT_TRUE(std::isnan(nominalCasingId_mm(177.8, kNaN)));
}

TEST(CasingProgramTest, HeaderGivesShoeSizeWeightAndTypeLoggerDepthFirst) {
    Diagnostics d;
    const std::vector<CasingString> p = readCasingProgram(
        headerWith(" CSGT.      SURFACE : Casing type\n CSGD.M     72.8 : Casing bottom driller\n"
                   " CSGL.M     73.2 : Casing bottom logger\n CSGS.MM    177.8 : Casing size\n"
                   " CSGW.KG/M  25.3 : Casing weight\n"),
        "h.las", &d);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_DOUBLE_EQ(p[0].bottom_m, 73.2);
    EXPECT_DOUBLE_EQ(p[0].size_mm, 177.8);
    EXPECT_DOUBLE_EQ(p[0].weight_kgPerM, 25.3);
    EXPECT_NEAR(p[0].innerDiameter_mm, 166.07, 0.01);
    EXPECT_EQ(p[0].type, "SURFACE");
    EXPECT_EQ(p[0].source, "~Parameter CSGL (CSGD 72.80 m), CSGS, CSGW");
    EXPECT_EQ(d.warningCount, 0u);
}

TEST(CasingProgramTest, BakerMnemonicsAndInchesAndFeet) {
    const std::vector<CasingString> p = readCasingProgram(
        headerWith(" CSIZ.IN  7 : Casing Size\n CBDR.FT  162 : Casing Bottom - Driller\n"), "h.las",
        nullptr);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_NEAR(p[0].bottom_m, 162 * 0.3048, 1e-12);
    EXPECT_NEAR(p[0].size_mm, 177.8, 1e-12);
    EXPECT_TRUE(std::isnan(p[0].weight_kgPerM));
    EXPECT_TRUE(std::isnan(p[0].innerDiameter_mm));  // no weight: unknown
    EXPECT_NE(describeCasing(p[0]).find("inner diameter unknown (no weight)"), std::string::npos)
        << describeCasing(p[0]);
}

TEST(CasingProgramTest, UnreadableItemsAreWarnedAboutWithTheirLine) {
    Diagnostics d;
    const std::vector<CasingString> p = readCasingProgram(
        headerWith(" CSGL.     0 m - 135 m : casing\n CSGS.MM  100 :\n"), "h.las", &d);
    EXPECT_TRUE(p.empty());
    ASSERT_EQ(d.warningCount, 2u);
    EXPECT_EQ(d.warnings[0].line, 7u);
    EXPECT_NE(d.warnings[0].message.find("CSGL '0 m - 135 m' is not a number"), std::string::npos);
    EXPECT_NE(d.warnings[1].message.find("no casing bottom depth"), std::string::npos);
    // A zero shoe depth (an empty field some writers fill with 0) is no casing.
    EXPECT_TRUE(
        readCasingProgram(headerWith(" CSGD.FT 0.0 :\n CSGS.IN 8.625 :\n"), "h.las", nullptr)
            .empty());
}

TEST(CasingProgramTest, CommandLineSpecWithWeightOrInnerDiameter) {
    std::string error;
    auto c = parseCasingSpec("88.3,7in,17lb/ft", error);
    ASSERT_TRUE(c) << error;
    EXPECT_DOUBLE_EQ(c->bottom_m, 88.3);
    EXPECT_DOUBLE_EQ(c->size_mm, 177.8);
    EXPECT_NEAR(c->innerDiameter_mm, 166.0652, 1e-3);
    EXPECT_EQ(c->source, "--casing");
    // Its text reads back to the same casing.
    auto back = parseCasingSpec(casingSpecText(*c), error);
    ASSERT_TRUE(back) << error;
    EXPECT_NEAR(back->innerDiameter_mm, c->innerDiameter_mm, 1e-9);
    c = parseCasingSpec("100, 177.8mm, 166.1mm", error);
    ASSERT_TRUE(c) << error;
    EXPECT_DOUBLE_EQ(c->innerDiameter_mm, 166.1);
    EXPECT_TRUE(std::isnan(c->weight_kgPerM));
    c = parseCasingSpec("100,7", error);  // a bare size is inches; no ID
    ASSERT_TRUE(c) << error;
    EXPECT_DOUBLE_EQ(c->size_mm, 177.8);
    EXPECT_TRUE(std::isnan(c->innerDiameter_mm));
    for (const char* bad :
         {"", "100", "x,7in", "100,7in,17", "100,7in,8in", "-5,7in", "100,7in,17lb/ft,3"}) {
        EXPECT_FALSE(parseCasingSpec(bad, error)) << bad;
        EXPECT_FALSE(error.empty()) << bad;
    }
}

TEST(CasingProgramTest, NarrowestStringWhoseShoeIsBelow) {
    CasingString surface, intermediate;
    surface.bottom_m = 300.0;
    surface.size_mm = 339.7;
    intermediate.bottom_m = 1200.0;
    intermediate.size_mm = 244.5;
    const std::vector<CasingString> p{surface, intermediate};
    EXPECT_EQ(casingAt(p, 100.0), &p[1]);
    EXPECT_EQ(casingAt(p, 1200.0), &p[1]);
    EXPECT_EQ(casingAt(p, 1200.1), nullptr);
}

TEST(CasingProgramTest, AStringHoldsOnlyOverItsOwnDepthsOfTheLog) {
    // A spliced log: 13 3/8 in to 300 m over the first run's rows (0-1190 m), 9 5/8 in to
    // 1200 m over the second's (1190-2500 m): the first run logged 300-1190 m in open hole.
    CasingString surface, intermediate;
    surface.bottom_m = 300.0;
    surface.size_mm = 339.7;
    surface.appliesFrom_m = 0.0;
    surface.appliesTo_m = 1190.0;
    intermediate.bottom_m = 1200.0;
    intermediate.size_mm = 244.5;
    intermediate.appliesFrom_m = 1190.0;
    intermediate.appliesTo_m = 2500.0;
    const std::vector<CasingString> p{surface, intermediate};
    EXPECT_EQ(casingAt(p, 100.0), &p[0]);
    EXPECT_EQ(casingAt(p, 300.1), nullptr);
    EXPECT_EQ(casingAt(p, 1189.9), nullptr);
    EXPECT_EQ(casingAt(p, 1190.1), &p[1]);
    EXPECT_EQ(casingAt(p, 1200.1), nullptr);
    EXPECT_NE(describeCasing(p[1]).find("holds over 1190.00-2500.00 m of the log"),
              std::string::npos)
        << describeCasing(p[1]);
}

TEST(CasingProgramTest, NumberedStringsWrittenReadBackTheSame) {
    CasingString surface, intermediate;
    surface.bottom_m = 300.0;
    surface.size_mm = 339.725;
    surface.weight_kgPerM = 68.0 * 1.48816394;  // 13 3/8 in 68 lb/ft
    surface.innerDiameter_mm = nominalCasingId_mm(surface.size_mm, surface.weight_kgPerM);
    surface.type = "SURFACE";
    surface.appliesFrom_m = 0.0;
    surface.appliesTo_m = 1189.975;
    intermediate.bottom_m = 1200.3;
    intermediate.size_mm = 244.475;
    intermediate.innerDiameter_mm = 220.5;  // given, no weight
    intermediate.appliesFrom_m = 1189.975;
    intermediate.appliesTo_m = 2500.0;
    std::string items;
    for (const LasParameter& p : casingParameters({surface, intermediate}))
        items += " " + p.mnemonic + "." + p.unit + " " + p.value + " : " + p.description + "\n";
    Diagnostics d;
    const std::vector<CasingString> read = readCasingProgram(headerWith(items), "h.las", &d);
    EXPECT_TRUE(d.warnings.empty());
    ASSERT_EQ(read.size(), 2u) << items;
    for (std::size_t k = 0; k < 2; ++k) {
        const CasingString& expected = k == 0 ? surface : intermediate;
        const CasingString& c = read[k];
        // Depths go through metres to millimetres and back: equal to rounding.
        EXPECT_NEAR(c.bottom_m, expected.bottom_m, 1e-9) << k;
        EXPECT_NEAR(c.appliesFrom_m, expected.appliesFrom_m, 1e-9) << k;
        EXPECT_NEAR(c.appliesTo_m, expected.appliesTo_m, 1e-9) << k;
        EXPECT_EQ(c.size_mm, expected.size_mm) << k;
        EXPECT_EQ(c.innerDiameter_mm, expected.innerDiameter_mm) << k;
        EXPECT_EQ(c.type, expected.type) << k;
    }
    EXPECT_EQ(read[0].weight_kgPerM, surface.weight_kgPerM);
    EXPECT_TRUE(std::isnan(read[1].weight_kgPerM));
    EXPECT_EQ(read[0].source, "~Parameter CSGL[1], CSGS[1], CSGW[1], CSID[1], CSRG[1]");
    EXPECT_NEAR(read[0].innerDiameter_mm, (13.375 - 2 * 0.480) * 25.4, 1e-9);
    // Numbered strings after the header's current one, up to the first number without a shoe.
    const std::vector<CasingString> both = readCasingProgram(
        headerWith(" CSGL.M 80 :\n CSGS.IN 7 :\n CSGL[1].M 50 :\n CSGL[3].M 90 :\n"), "h.las",
        nullptr);
    ASSERT_EQ(both.size(), 2u);
    EXPECT_DOUBLE_EQ(both[0].bottom_m, 80.0);
    EXPECT_DOUBLE_EQ(both[1].bottom_m, 50.0);
    EXPECT_TRUE(std::isnan(both[1].appliesFrom_m));
    // An interval that is not two depths is warned about and the string holds everywhere.
    Diagnostics bad;
    const std::vector<CasingString> loose =
        readCasingProgram(headerWith(" CSGL[1].M 50 :\n CSRG[1].M 10 :\n"), "h.las", &bad);
    ASSERT_EQ(loose.size(), 1u);
    EXPECT_TRUE(std::isnan(loose[0].appliesTo_m));
    ASSERT_EQ(bad.warnings.size(), 1u);
    EXPECT_NE(bad.warnings[0].message.find("CSRG[1] '10' is not two depths"), std::string::npos);
}

TEST(CasingProgramTest, RealFmiAndCmiHeadersGiveTheirCasing) {
    const auto fmi = caliper3d::test::sharedData() / "real" / "1AA063409108W400_FMI_SONIC_MAIN.las";
    CALIPER3D_REQUIRE_DATA(fmi);
    const LogInfo info = describeLog(fmi.string(), ReadOptions{});
    ASSERT_EQ(info.casing.size(), 1u);
    EXPECT_DOUBLE_EQ(info.casing[0].bottom_m, 73.2);  // CSGL (logger), not CSGD 72.8
    EXPECT_DOUBLE_EQ(info.casing[0].size_mm, 177.8);
    EXPECT_NEAR(info.casing[0].innerDiameter_mm, 166.07, 0.01);  // 7 in 17 lb/ft (25.3 kg/m)
    EXPECT_NE(formatLogInfo(info).find("casing:    177.8 mm (7.000 in), 25.3 kg/m (17.00 lb/ft), "
                                       "shoe at 73.20 m; nominal ID 166.07 mm (API 5CT)"),
              std::string::npos)
        << formatLogInfo(info);
}

// The real oriented caliper logs in ../shared/data/real are detected with the
// right roles, units and arm counts. Skips when the data are absent.
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "io/log_reader.h"
#include "test_support.h"

using namespace caliper3d::io;

namespace {
std::filesystem::path real(const char* name) {
    return caliper3d::test::sharedData() / "real" / name;
}

std::string roleOf(const LogInfo& info, const std::string& mnemonic) {
    for (const CurveInfo& c : info.curves)
        if (c.mnemonic == mnemonic) return c.role;
    return "(absent)";
}
}  // namespace

TEST(RealLogsTest, StarSixArmImagerReadsRadiiInMillimetresAndBitSizeParameter) {
    const auto path = real("1AA072209208W400_WL_0477502_STAR_FIELD.las");
    CALIPER3D_REQUIRE_DATA(path);
    const LoadedLog log = loadCaliperLog(path.string(), ReadOptions{});
    EXPECT_EQ(log.table.armCount, 6);
    EXPECT_EQ(roleOf(log.info, "RAD1QH"), "radius");
    EXPECT_EQ(roleOf(log.info, "RAD6QH"), "radius");
    EXPECT_EQ(roleOf(log.info, "AZSTQH"), "pad-1 azimuth");
    EXPECT_EQ(roleOf(log.info, "DEVSTQH"), "deviation");
    EXPECT_EQ(roleOf(log.info, "RBSTQH"), "relative bearing");
    ASSERT_FALSE(log.table.bitSize_mm.empty());
    EXPECT_NEAR(log.table.bitSize_mm.front(), 156.0, 0.5);
    EXPECT_TRUE(log.table.hazi_deg.empty());
    EXPECT_NEAR(log.info.step_m, 0.0762, 1e-6);
    // Radii are millimetres, tool axis to pad: a 156 mm hole gives radii near 78 mm.
    std::size_t plausible = 0;
    for (double r : log.table.radius_mm) plausible += (r > 30.0 && r < 200.0);
    EXPECT_GT(plausible, log.table.radius_mm.size() / 2);
}

TEST(RealLogsTest, FmiFourArmImagerTurnsPadPairDiametersIntoRadii) {
    const auto path = real("1AA063409108W400_FMI_SONIC_MAIN.las");
    CALIPER3D_REQUIRE_DATA(path);
    const LoadedLog log = loadCaliperLog(path.string(), ReadOptions{});
    ASSERT_EQ(log.table.armCount, 4);
    EXPECT_EQ(roleOf(log.info, "C1"), "diameter");
    EXPECT_EQ(roleOf(log.info, "C2"), "diameter");
    EXPECT_EQ(roleOf(log.info, "P1AZ"), "pad-1 azimuth");
    EXPECT_EQ(roleOf(log.info, "HAZI"), "hole azimuth");
    EXPECT_EQ(roleOf(log.info, "RB"), "relative bearing");
    EXPECT_EQ(roleOf(log.info, "DEVIM"), "deviation");
    EXPECT_EQ(roleOf(log.info, "BS"), "bit size");
    EXPECT_NEAR(log.info.step_m, 0.1524, 1e-6);
    // r1 = r3 = C1/2, r2 = r4 = C2/2
    for (std::size_t row = 0; row < log.table.rowCount(); row += 97) {
        const double* r = log.table.radii(row);
        if (std::isnan(r[0])) continue;
        EXPECT_DOUBLE_EQ(r[0], r[2]);
        EXPECT_DOUBLE_EQ(r[1], r[3]);
    }
    EXPECT_EQ(roleOf(log.info, "DEPTH"), "second depth (checked against the index)");
    bool warned = false;
    for (const Warning& w : log.info.diagnostics.warnings)
        warned = warned || w.message.find("DEPTH differs from the index DEPT on 122 rows") !=
                               std::string::npos;
    EXPECT_TRUE(warned);
    EXPECT_NEAR(log.info.bitSize_mm, 156.0, 1.0);
    EXPECT_NEAR(log.info.bitSizeMax_mm, 251.0, 1.0);
    // The bit size curve steps 251 -> 159 -> 156 mm.
    double lo = 1e9, hi = 0;
    for (double b : log.table.bitSize_mm)
        if (std::isfinite(b)) lo = std::min(lo, b), hi = std::max(hi, b);
    EXPECT_NEAR(lo, 156.0, 1.0);
    EXPECT_NEAR(hi, 251.0, 1.0);
}

TEST(RealLogsTest, FortyFingerRadiiOnlyTextReadsAsFortyArms) {
    const auto path = real("multifinger40_data.txt");
    CALIPER3D_REQUIRE_DATA(path);
    ReadOptions options;
    options.radiusUnit = LengthUnit::Millimetre;
    const LoadedLog log = loadCaliperLog(path.string(), options);
    EXPECT_EQ(log.table.armCount, 40);
    EXPECT_EQ(log.table.rowCount(), 201u);
    EXPECT_DOUBLE_EQ(log.table.radii(0)[0], 115.43);
    EXPECT_DOUBLE_EQ(log.table.depth_m[1], options.rowStep_m);
    EXPECT_GE(log.info.diagnostics.warningCount, 1u);
}

// docs/formats.md shows `caliper3d info` on the reference logs, run from
// ../shared/data; it must be what the reader prints today.
TEST(RealLogsTest, FormatsReferenceShowsTheInfoPrintedToday) {
    const auto data = caliper3d::test::sharedData();
    CALIPER3D_REQUIRE_DATA(data / "real");
    std::string expected;
    for (const std::string& name : caliper3d::test::referenceLogs()) {
        if (!std::filesystem::exists(data / name)) continue;
        LogInfo info = describeLog((data / name).string(), ReadOptions{});
        // As printed from ../shared/data: paths relative to it.
        const std::string shown = name;
        info.file = shown;
        for (Warning& w : info.diagnostics.warnings) w.file = shown;
        expected += (expected.empty() ? "" : "\n") + formatLogInfo(info);
    }
    std::ifstream in(std::string(CALIPER3D_SOURCE_DIR) + "/docs/formats.md");
    ASSERT_TRUE(in) << "docs/formats.md not found";
    const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(doc.find("```\n" + expected + "```\n"), std::string::npos)
        << "docs/formats.md is out of date; today's output:\n"
        << expected;
}

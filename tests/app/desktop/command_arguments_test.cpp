#include "app/desktop/command_arguments.h"

#include <gtest/gtest.h>

using namespace caliper3d;

namespace {

// Options far from every default, each one a value a round trip could lose.
app::LoadOptions unusualOptions() {
    app::LoadOptions o;
    o.read.armCount = 8;
    o.read.depthUnit = io::LengthUnit::Foot;
    o.read.radiusUnit = io::LengthUnit::Centimetre;
    o.read.roles.radii = {"RAD1", "RAD2", "RAD3", "RAD4"};
    o.read.roles.diameters = {"C1", "C2"};
    o.read.rowStep_m = 0.0254;
    o.read.nullPolicy = io::NullPolicy::Declared;
    o.read.bitSize_mm = 155.575;  // 6 1/8 in
    o.splinePoints = 36;
    o.segmentLength_m = 2.5;
    o.shapeTolerance_mm = 0.3;
    o.radialExaggeration = 37.5;
    o.steepInclination_deg = 22.25;
    o.toolReach_mm = 254.0 / 3.0;  // not a short decimal
    o.colour.quantity = "GR";
    o.colour.range = std::make_pair(-10.125, 40.0 / 3.0);
    return o;
}

}  // namespace

TEST(CommandArgumentsTest, WellsAndOptionsRoundTripThroughTheCommandLineParser) {
    const app::LoadOptions o = unusualOptions();
    std::vector<app::WellSource> wells(2);
    wells[0] = {"/data/a well.las", "/data/a survey.csv",
                reconstruction::Wellhead{512300.25, 6801200.5, 25.5}};
    wells[1] = {"-odd name.txt", "/data/b.csv",
                reconstruction::Wellhead{512400.0, 6801100.0, -3.0}};
    const app::ParsedWells back = app::parseWellArguments(app::wellArguments(wells, o));

    ASSERT_EQ(back.wells.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(back.wells[i].path, wells[i].path);
        EXPECT_EQ(back.wells[i].surveyPath, wells[i].surveyPath);
        ASSERT_TRUE(back.wells[i].wellhead);
        EXPECT_EQ(back.wells[i].wellhead->easting_m, wells[i].wellhead->easting_m);
        EXPECT_EQ(back.wells[i].wellhead->northing_m, wells[i].wellhead->northing_m);
        EXPECT_EQ(back.wells[i].wellhead->elevation_m, wells[i].wellhead->elevation_m);
    }
    const app::LoadOptions& b = back.options;
    EXPECT_EQ(b.read.armCount, 8);
    EXPECT_EQ(b.read.depthUnit, io::LengthUnit::Foot);
    EXPECT_EQ(b.read.radiusUnit, io::LengthUnit::Centimetre);
    EXPECT_EQ(b.read.roles.radii, o.read.roles.radii);
    EXPECT_EQ(b.read.roles.diameters, o.read.roles.diameters);
    EXPECT_EQ(b.read.rowStep_m, o.read.rowStep_m);
    EXPECT_EQ(b.read.nullPolicy, io::NullPolicy::Declared);
    ASSERT_TRUE(b.read.bitSize_mm);
    EXPECT_EQ(*b.read.bitSize_mm, *o.read.bitSize_mm);
    EXPECT_EQ(b.splinePoints, 36);
    EXPECT_EQ(b.segmentLength_m, o.segmentLength_m);
    EXPECT_EQ(b.shapeTolerance_mm, o.shapeTolerance_mm);
    EXPECT_EQ(b.radialExaggeration, o.radialExaggeration);
    EXPECT_EQ(b.steepInclination_deg, o.steepInclination_deg);
    EXPECT_EQ(b.toolReach_mm, o.toolReach_mm);
    EXPECT_EQ(b.colour.quantity, "GR");
    ASSERT_TRUE(b.colour.range);
    EXPECT_EQ(b.colour.range->first, o.colour.range->first);
    EXPECT_EQ(b.colour.range->second, o.colour.range->second);
    EXPECT_TRUE(b == o) << "the options compare equal by value";
    EXPECT_EQ(back.wells, wells);
}

TEST(CommandArgumentsTest, DefaultOptionsAreLeftOffTheCommandLine) {
    const QStringList args = app::wellArguments({{"w.las", "", {}}}, {});
    EXPECT_EQ(args, (QStringList{"--", "w.las"}));
    app::LoadOptions o;
    o.read.bitSize_mm = 215.9;
    EXPECT_EQ(app::wellArguments({{"w.las", "", {}}}, o),
              (QStringList{"--bit-size", "215.9mm", "--", "w.las"}));
}

TEST(CommandArgumentsTest, DefaultsRoundTripWithoutOptionalValues) {
    const app::LoadOptions o;
    const app::ParsedWells back =
        app::parseWellArguments(app::wellArguments({{"w.las", "", {}}}, o));
    ASSERT_EQ(back.wells.size(), 1u);
    EXPECT_TRUE(back.wells[0].surveyPath.empty());
    EXPECT_FALSE(back.wells[0].wellhead);
    EXPECT_FALSE(back.options.read.bitSize_mm);
    EXPECT_FALSE(back.options.read.depthUnit);
    EXPECT_FALSE(back.options.colour.range);
    EXPECT_EQ(back.options.toolReach_mm, o.toolReach_mm);
    EXPECT_EQ(back.options.colour.quantity, "departure");
}

TEST(CommandArgumentsTest, SurveysForSomeWellsOnlyCannotBeWrittenAsOneCommand) {
    const std::vector<app::WellSource> wells{{"a.las", "a.csv", {}}, {"b.las", "", {}}};
    EXPECT_THROW(app::wellArguments(wells, {}), std::invalid_argument);
    const std::vector<app::WellSource> heads{{"a.las", "", reconstruction::Wellhead{}},
                                             {"b.las", "", {}}};
    EXPECT_THROW(app::wellArguments(heads, {}), std::invalid_argument);
}

TEST(CommandArgumentsTest, ExportArgumentsNameTheVerbTheOutputAndAskForProgress) {
    const QStringList args = app::exportArguments({{"w.las", "", {}}}, {}, "/tmp/out.glb");
    ASSERT_GE(args.size(), 5);
    EXPECT_EQ(args[0], "export");
    EXPECT_EQ(args.mid(1, 3), (QStringList{"-o", "/tmp/out.glb", "--progress"}));
    EXPECT_EQ(args.back(), "w.las");
    EXPECT_EQ(args[args.size() - 2], "--");
}

TEST(CommandArgumentsTest, AMalformedArgumentIsAUsageError) {
    EXPECT_THROW(app::parseWellArguments({"--bit-size", "huge", "w.las"}), app::UsageError);
    EXPECT_THROW(app::parseWellArguments({"--no-such-option", "w.las"}), app::UsageError);
}

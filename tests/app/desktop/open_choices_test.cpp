#include "app/desktop/open_choices.h"

#include <gtest/gtest.h>

using namespace caliper3d;

namespace {
// The look of a window opened on the bundled example: its 8.5 in bit size must not follow.
app::LoadOptions exampleLook() {
    app::LoadOptions look;
    look.read.bitSize_mm = 215.9;
    look.read.radiusUnit = io::LengthUnit::Inch;
    look.read.roles.radii = {"R1", "R2"};
    look.radialExaggeration = 50.0;
    look.colour.quantity = "ellipticity";
    look.colour.range = std::make_pair(0.0, 0.5);
    return look;
}
}  // namespace

TEST(OpenChoicesTest, TakesOnlyTheLookFromTheWellsShown) {
    app::OpenChoices choices;
    choices.path = "/data/star.las";
    const app::ParsedWells r = app::openRequestFrom(choices, exampleLook());
    ASSERT_EQ(r.wells.size(), 1u);
    EXPECT_EQ(r.wells[0].path, "/data/star.las");
    EXPECT_FALSE(r.options.read.bitSize_mm) << "the example's bit size was carried over";
    EXPECT_FALSE(r.options.read.radiusUnit);
    EXPECT_TRUE(r.options.read.roles.radii.empty());
    EXPECT_TRUE(r.wells[0].surveyPath.empty());
    EXPECT_FALSE(r.wells[0].wellhead);
    EXPECT_EQ(r.options.radialExaggeration, 50.0);
    EXPECT_EQ(r.options.colour.quantity, "ellipticity");
    ASSERT_TRUE(r.options.colour.range);
    EXPECT_EQ(r.options.colour.range->second, 0.5);
}

TEST(OpenChoicesTest, GivesTheChosenOptions) {
    app::OpenChoices choices;
    choices.path = "/data/w.txt";
    choices.options = {{"radii", " RAD1, RAD2 ,RAD3 "},
                       {"depth-unit", "ft"},
                       {"radius-unit", "mm"},
                       {"bit-size", "6.125in"},
                       {"arms", "3"},
                       {"survey", "/data/w-survey.csv"},
                       {"wellhead", "512300,6801200,25.5"}};
    const app::ParsedWells r = app::openRequestFrom(choices, exampleLook());
    EXPECT_EQ(r.options.read.roles.radii, (std::vector<std::string>{"RAD1", "RAD2", "RAD3"}));
    EXPECT_EQ(r.options.read.depthUnit, io::LengthUnit::Foot);
    EXPECT_EQ(r.options.read.radiusUnit, io::LengthUnit::Millimetre);
    ASSERT_TRUE(r.options.read.bitSize_mm);
    EXPECT_NEAR(*r.options.read.bitSize_mm, 155.575, 1e-9);
    EXPECT_EQ(r.options.read.armCount, 3);
    EXPECT_EQ(r.wells[0].surveyPath, "/data/w-survey.csv");
    ASSERT_TRUE(r.wells[0].wellhead);
    EXPECT_EQ(r.wells[0].wellhead->easting_m, 512300.0);
    EXPECT_EQ(r.wells[0].wellhead->northing_m, 6801200.0);
    EXPECT_EQ(r.wells[0].wellhead->elevation_m, 25.5);
}

TEST(OpenChoicesTest, MalformedChoicesFailWithTheCommandLinesMessage) {
    app::OpenChoices choices;
    choices.path = "w.las";
    choices.options["bit-size"] = "eight";
    try {
        app::openRequestFrom(choices, {});
        FAIL() << "no error";
    } catch (const app::UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("--bit-size"), std::string::npos) << e.what();
    }
    choices.options["bit-size"].clear();
    choices.options["wellhead"] = "1,2";
    EXPECT_THROW(app::openRequestFrom(choices, {}), app::UsageError);
    choices.options["wellhead"].clear();
    choices.options["radii"] = "ONLYONE";
    EXPECT_THROW(app::openRequestFrom(choices, {}), app::UsageError);
    choices.options = {{"no-such-option", "1"}};
    EXPECT_THROW(app::openRequestFrom(choices, {}), app::UsageError);
}

TEST(OpenChoicesTest, AFileNamedLikeAnOptionIsAFile) {
    app::OpenChoices choices;
    choices.path = "--bit-size";
    const app::ParsedWells r = app::openRequestFrom(choices, {});
    ASSERT_EQ(r.wells.size(), 1u);
    EXPECT_EQ(r.wells[0].path, "--bit-size");
    EXPECT_FALSE(r.options.read.bitSize_mm);
}

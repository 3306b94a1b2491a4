// caliper3d render --pick: the pixel of the picture names the section the report lists there.
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include "cli_run.h"
#include "test_support.h"

namespace {

using caliper3d::test::CommandRun;
using caliper3d::test::runCaliper3d;
using caliper3d::test::scratch;

std::map<std::string, std::string> keyValues(const std::string& text) {
    std::map<std::string, std::string> out;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        const std::size_t eq = line.find('=');
        if (eq != std::string::npos && line.find(' ') == std::string::npos)
            out[line.substr(0, eq)] = line.substr(eq + 1);
    }
    return out;
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> out;
    std::stringstream in(line);
    for (std::string field; std::getline(in, field, ',');) out.push_back(field);
    if (!line.empty() && line.back() == ',') out.emplace_back();
    return out;
}

// A 10 m vertical gauge hole (215.9 mm), a section every centimetre.
std::string circleWell() {
    const std::string log = scratch("pick_circle.txt").string();
    const CommandRun r =
        runCaliper3d("synth -o " + log + " --profile circle --length 10 --step 0.01");
    EXPECT_EQ(r.status, 0) << r.output;
    return log;
}

}  // namespace

TEST(RenderPickTest, PixelRightOfTheHoleViewsCentreNamesTheEastWallAndTheReportsRow) {
    const std::string log = circleWell();
    const std::string png = scratch("pick_circle.png").string();
    // Looking down the hole from MD 2 m, high side (north) up: east is on the right. The middle
    // row (200 of 401, counted from the top) and 150 pixels right of the centre.
    const CommandRun r =
        runCaliper3d("render " + log + " -o " + png +
                         " --view hole --at 2 --width 401 --height 401 --pick 350,200",
                     false);
    ASSERT_EQ(r.status, 0) << r.output;
    const auto picked = keyValues(r.output);
    ASSERT_EQ(picked.count("section"), 1u) << r.output;
    EXPECT_EQ(picked.at("picked"), "350,200");
    EXPECT_EQ(picked.at("well"), "0");
    EXPECT_EQ(picked.at("well_name"), "pick_circle");
    EXPECT_NEAR(std::stod(picked.at("angle_from_high_side_deg")), 90.0, 0.05);
    EXPECT_NEAR(std::stod(picked.at("angle_azimuth_deg")), 90.0, 0.05);
    EXPECT_NEAR(std::stod(picked.at("radius_mm")), 215.9 / 2.0, 0.01);
    // The ray leans from the axis by tan a = (350.5 / 401 x 2 - 1) tan(0.15) (the hole view's
    // 0.3 rad field of view), so it meets the 107.95 mm wall 107.95 mm / tan a deeper, within
    // a row and the drawn polygon's millimetre.
    const double tanA = (2.0 * 350.5 / 401.0 - 1.0) * std::tan(0.15);
    const double md = std::stod(picked.at("md_m"));
    EXPECT_NEAR(md, 2.0 + 0.10795 / tanA, 0.01 + 0.001 / tanA);
    EXPECT_EQ(std::stod(picked.at("section")), std::round(md / 0.01));
    EXPECT_EQ(picked.at("class"), "in_gauge");

    // Every report column is what 'caliper3d report' writes for that section.
    const std::string csv = scratch("pick_circle.csv").string();
    const CommandRun report = runCaliper3d("report " + log + " -o " + csv);
    ASSERT_EQ(report.status, 0) << report.output;
    std::ifstream in(csv);
    std::string header, line;
    std::getline(in, header);
    const std::vector<std::string> names = split(header);
    const auto section = static_cast<std::size_t>(std::stoul(picked.at("section")));
    for (std::size_t i = 0; i <= section; ++i) ASSERT_TRUE(std::getline(in, line));
    const std::vector<std::string> values = split(line);
    ASSERT_EQ(values.size(), names.size());
    for (std::size_t k = 0; k < names.size(); ++k) {
        ASSERT_EQ(picked.count(names[k]), 1u) << names[k];
        EXPECT_EQ(picked.at(names[k]), values[k]) << names[k];
    }
}

TEST(RenderPickTest, PixelsAreCountedFromTheTopLeft) {
    const std::string log = circleWell();
    const std::string png = scratch("pick_top.png").string();
    // Above the centre the picture shows the high side (north), below it the low side.
    for (const auto& [pixel, azimuth] :
         std::vector<std::pair<std::string, double>>{{"200,60", 0.0}, {"200,340", 180.0}}) {
        const CommandRun r =
            runCaliper3d("render " + log + " -o " + png +
                             " --view hole --at 2 --width 401 --height 401 --pick " + pixel,
                         false);
        ASSERT_EQ(r.status, 0) << r.output;
        const auto picked = keyValues(r.output);
        ASSERT_EQ(picked.count("angle_azimuth_deg"), 1u) << r.output;
        const double off =
            std::remainder(std::stod(picked.at("angle_azimuth_deg")) - azimuth, 360.0);
        EXPECT_NEAR(off, 0.0, 0.05) << pixel;
    }
}

TEST(RenderPickTest, APixelThatShowsNoWallPicksNothingAndAPixelOutsideIsAUsageError) {
    const std::string log = circleWell();
    const std::string png = scratch("pick_miss.png").string();
    // Straight down the axis the ray leaves through the bottom of the hole.
    const CommandRun miss =
        runCaliper3d("render " + log + " -o " + png +
                         " --view hole --at 2 --width 401 --height 401 --pick 200,200",
                     false);
    EXPECT_EQ(miss.status, 0) << miss.output;
    EXPECT_NE(miss.output.find("nothing picked at 200,200\n"), std::string::npos) << miss.output;
    EXPECT_EQ(keyValues(miss.output).count("section"), 0u) << miss.output;

    const CommandRun outside =
        runCaliper3d("render " + log + " -o " + png + " --width 64 --height 48 --pick 64,10");
    EXPECT_EQ(outside.status, 2) << outside.output;
    EXPECT_NE(outside.output.find("--pick takes X,Y"), std::string::npos) << outside.output;
}

// caliper3d render's default picture and --depth (app/render_command.cpp).
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <QImage>

#include "cli_run.h"
#include "io/column_text_writer.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "scenegraph/label_style.h"
#include "test_support.h"

namespace {

using caliper3d::test::CommandRun;
using caliper3d::test::runCaliper3d;
using caliper3d::test::scratch;
namespace io = caliper3d::io;
namespace reconstruction = caliper3d::reconstruction;
namespace scenegraph = caliper3d::scenegraph;

// A vertical gauge hole (8.5 in) 1 km long, sampled every 10 cm.
std::string kilometreWell() {
    const auto path = scratch("render_1km.txt");
    if (!std::filesystem::exists(path))
        caliper3d::io::writeColumnTextFile(
            path.string(), caliper3d::reconstruction::makeSyntheticWell(
                               caliper3d::reconstruction::syntheticProfile("circle", 1000.0, 0.1)));
    return path.string();
}

// Across each picture row between 30 % and 70 % of its height, the longest run of pixels
// that are not the background, left of the colour legend (the right fifth): the median of
// those runs is the drawn wall's width (a tick mark joins it on a few rows only; the labels
// stand clear of it).
int medianWallWidth(const QImage& picture) {
    const QRgb background = picture.pixel(0, 0);
    std::vector<int> runs;
    for (int y = picture.height() * 3 / 10; y < picture.height() * 7 / 10; ++y) {
        int longest = 0, run = 0;
        for (int x = 0; x < picture.width() * 7 / 10; ++x) {
            run = picture.pixel(x, y) != background ? run + 1 : 0;
            longest = std::max(longest, run);
        }
        runs.push_back(longest);
    }
    std::nth_element(runs.begin(), runs.begin() + static_cast<long>(runs.size() / 2), runs.end());
    return runs[runs.size() / 2];
}

// Pixels within 8 (of 255) of `colour` (0-1) in each channel, in rows [y0, y1).
int pixelsOfColour(const QImage& picture, const float colour[3], int y0, int y1) {
    int count = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = 0; x < picture.width(); ++x) {
            const QRgb p = picture.pixel(x, y);
            const int rgb[3] = {qRed(p), qGreen(p), qBlue(p)};
            bool close = true;
            for (int c = 0; c < 3; ++c)
                close = close && std::abs(rgb[c] - int(colour[c] * 255.0f + 0.5f)) <= 8;
            count += close ? 1 : 0;
        }
    return count;
}

// Rows (of the middle tenth of columns) where something is drawn: top and bottom.
std::pair<int, int> drawnRows(const QImage& picture) {
    const QRgb background = picture.pixel(0, 0);
    int top = picture.height(), bottom = -1;
    for (int y = 0; y < picture.height(); ++y)
        for (int x = picture.width() * 45 / 100; x < picture.width() * 55 / 100; ++x)
            if (picture.pixel(x, y) != background) {
                top = std::min(top, y);
                bottom = std::max(bottom, y);
            }
    return {top, bottom};
}

TEST(RenderCommandTest, DefaultPictureOfAKilometreWellDrawsTheHoleAsATube) {
    const std::string png = scratch("render_1km.png").string();
    const CommandRun r = runCaliper3d("render " + kilometreWell() + " -o " + png);
    ASSERT_EQ(r.status, 0) << r.output;
    const QImage picture(QString::fromStdString(png));
    ASSERT_EQ(picture.height(), 768);
    // Radii x 100 (picture_scale.h): at least 1.5 % of 768 pixels across, less the
    // foreshortening of the iso view.
    EXPECT_GT(medianWallWidth(picture), 10) << "radii as logged would be a line";
    // Its name (the file's) at the wellhead, at the top; depth labels down the picture.
    EXPECT_GT(pixelsOfColour(picture, caliper3d::scenegraph::kNameColour, 0, 80), 60);
    EXPECT_GT(pixelsOfColour(picture, caliper3d::scenegraph::kLabelColour, 80, 700), 500);
    // Radii as logged: the path's 2-pixel line, the hole a fraction of a pixel.
    const std::string asLogged = scratch("render_1km_x1.png").string();
    ASSERT_EQ(
        runCaliper3d("render " + kilometreWell() + " -o " + asLogged + " --exaggerate 1").status,
        0);
    EXPECT_LT(medianWallWidth(QImage(QString::fromStdString(asLogged))), 5);
}

// Across each picture row between 30 % and 70 % of its height, left of the colour legend,
// the runs of pixels that are not the background: their median count (a tick or label joins
// a few rows only).
int medianDrawnRuns(const QImage& picture) {
    const QRgb background = picture.pixel(0, 0);
    std::vector<int> counts;
    for (int y = picture.height() * 3 / 10; y < picture.height() * 7 / 10; ++y) {
        int runs = 0;
        bool inRun = false;
        for (int x = 0; x < picture.width() * 7 / 10; ++x) {
            const bool drawn = picture.pixel(x, y) != background;
            runs += drawn && !inRun ? 1 : 0;
            inRun = drawn;
        }
        counts.push_back(runs);
    }
    std::nth_element(counts.begin(), counts.begin() + static_cast<long>(counts.size() / 2),
                     counts.end());
    return counts[counts.size() / 2];
}

TEST(RenderCommandTest, TwoWellsTenMetresApartAreDrawnApart) {
    // Two 1 km gauge holes, their wellheads 10 m apart north, seen from the east: alone each
    // would be drawn x 100 (22 m across, the two one band); the default keeps them apart (x 20).
    const std::string well = kilometreWell();
    const std::string wells =
        well + " --wellhead 0,0,0 " + well + " --wellhead 0,10,0 --view east -o ";
    const std::string png = scratch("render_two_wells.png").string();
    const CommandRun r = runCaliper3d("render " + wells + png);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(medianDrawnRuns(QImage(QString::fromStdString(png))), 2);
    // A factor given is drawn as given, touching or not.
    const std::string given = scratch("render_two_wells_x100.png").string();
    ASSERT_EQ(runCaliper3d("render " + wells + given + " --exaggerate 100").status, 0);
    EXPECT_EQ(medianDrawnRuns(QImage(QString::fromStdString(given))), 1);
}

TEST(RenderCommandTest, DefaultPictureOfAShortLogDeepInAWellFramesTheLog) {
    // 10 m of 8.5 in hole logged from 2000 m: the path from the wellhead is 200 times longer.
    const auto path = scratch("render_deep_10m.txt");
    io::SectionTable table =
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("circle", 10.0, 0.01));
    for (double& md : table.depth_m) md += 2000.0;
    io::writeColumnTextFile(path.string(), table);
    const std::string png = scratch("render_deep_10m.png").string();
    const CommandRun r =
        runCaliper3d("render " + path.string() + " -o " + png + " --pick 512,384", false);
    ASSERT_EQ(r.status, 0) << r.output;
    // The picture's centre is the log: a section of it, not the background.
    const auto at = r.output.find("\nsection=");
    ASSERT_NE(at, std::string::npos) << r.output;
    const auto md = r.output.find("\nmd_m=");
    ASSERT_NE(md, std::string::npos) << r.output;
    const double pickedMd = std::stod(r.output.substr(md + 6));
    EXPECT_GE(pickedMd, 2000.0);
    EXPECT_LE(pickedMd, 2010.0);
    // The 10 m fill the picture's height (the dashed path above runs out of it), drawn at
    // the exaggeration a 10 m picture needs: 1, the 215.9 mm hole about 13 of the 620 pixels
    // the 10 m span (the 2 km from the wellhead would have called for x 300).
    const QImage picture(QString::fromStdString(png));
    const auto [top, bottom] = drawnRows(picture);
    EXPECT_LT(top, picture.height() / 10);
    EXPECT_GT(bottom - top, picture.height() * 7 / 10);
    EXPECT_GT(medianWallWidth(picture), 8);
    EXPECT_LT(medianWallWidth(picture), 25);
    // Its name at the top of the log, in the picture.
    EXPECT_GT(pixelsOfColour(picture, scenegraph::kNameColour, 0, picture.height()), 60);
}

TEST(RenderCommandTest, DepthDrawsOnlyTheIntervalAndFramesIt) {
    const std::string png = scratch("render_1km_depth.png").string();
    const CommandRun r =
        runCaliper3d("render " + kilometreWell() + " -o " + png + " --depth 400,500", false);
    ASSERT_EQ(r.status, 0) << r.output;
    // 400.0, 400.1, ... 500.0 m: the sections drawn, in segments of 100 rows (10 m).
    EXPECT_NE(r.output.find(": 1001 sections, 10 segments"), std::string::npos) << r.output;
    // The 100 m drawn fill the picture's height, as a whole well's length does; and they are
    // exaggerated for 100 m (x 10), not for 1 km.
    const QImage picture(QString::fromStdString(png));
    const auto [top, bottom] = drawnRows(picture);
    EXPECT_GT(bottom - top, picture.height() * 7 / 10);
    EXPECT_GT(medianWallWidth(picture), 10);
    EXPECT_LT(medianWallWidth(picture), 40);
}

TEST(RenderCommandTest, DepthOutsideTheLogOrUpsideDownIsAUsageError) {
    const std::string png = scratch("render_depth_error.png").string();
    const std::string well = kilometreWell();
    const CommandRun beyond = runCaliper3d("render " + well + " -o " + png + " --depth 900,1200");
    EXPECT_EQ(beyond.status, 2);
    EXPECT_NE(beyond.output.find("--depth 900,1200 is outside the logged depths of " + well +
                                 " (0.00 to 1000.00 m)"),
              std::string::npos)
        << beyond.output;
    const CommandRun above = runCaliper3d("render " + well + " -o " + png + " --depth -5,100");
    EXPECT_EQ(above.status, 2);
    EXPECT_NE(above.output.find("outside the logged depths"), std::string::npos) << above.output;
    const CommandRun reversed = runCaliper3d("render " + well + " -o " + png + " --depth 500,400");
    EXPECT_EQ(reversed.status, 2);
    EXPECT_NE(reversed.output.find("TOP must lie above BOTTOM"), std::string::npos)
        << reversed.output;
    const CommandRun empty = runCaliper3d("render " + well + " -o " + png + " --depth 400,400");
    EXPECT_EQ(empty.status, 2);
    const CommandRun malformed = runCaliper3d("render " + well + " -o " + png + " --depth 400");
    EXPECT_EQ(malformed.status, 2);
    EXPECT_NE(malformed.output.find("--depth takes TOP,BOTTOM"), std::string::npos)
        << malformed.output;
}

TEST(RenderCommandTest, HoleViewWithinTheDepthInterval) {
    const std::string png = scratch("render_depth_hole.png").string();
    const std::string well = kilometreWell();
    EXPECT_EQ(runCaliper3d("render " + well + " -o " + png +
                           " --depth 400,500 --view hole --width 64 --height 48")
                  .status,
              0);
    const CommandRun outside =
        runCaliper3d("render " + well + " -o " + png + " --depth 400,500 --view hole --at 600");
    EXPECT_EQ(outside.status, 2);
    EXPECT_NE(outside.output.find("outside --depth 400,500 (400.00 to 500.00 m)"),
              std::string::npos)
        << outside.output;
}

}  // namespace

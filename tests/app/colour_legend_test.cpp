// The wall's colours from the command line: --colour-by and --colour-range, and the legend
// every rendered picture carries (its bar in the map's colours, its text).
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <QColor>
#include <QImage>

#include "cli_run.h"
#include "reconstruction/mesh/colour_map.h"
#include "scenegraph/colour_legend.h"
#include "test_support.h"

using caliper3d::test::CommandRun;
namespace rc = caliper3d::reconstruction;

namespace {

CommandRun run(const std::string& arguments) {
    return caliper3d::test::runCaliper3d(arguments);
}

std::string washoutLog() {
    static const std::string log = [] {
        const auto path = caliper3d::test::scratch("colour_washout.txt");
        const CommandRun r =
            run("synth -o " + path.string() + " --profile washout --length 40 --step 0.1");
        EXPECT_EQ(r.status, 0) << r.output;
        return path.string();
    }();
    return log;
}

// The pixel at (x, y) of the legend's frame ([-1, 1] across and up the picture).
QColor at(const QImage& image, double x, double y) {
    const int px = static_cast<int>((x + 1.0) / 2.0 * image.width());
    const int py = static_cast<int>((1.0 - y) / 2.0 * image.height());
    return image.pixelColor(px, py);
}

void expectColour(const QColor& pixel, std::uint32_t expected, int tolerance = 4) {
    EXPECT_NEAR(pixel.red(), rc::red(expected), tolerance);
    EXPECT_NEAR(pixel.green(), rc::green(expected), tolerance);
    EXPECT_NEAR(pixel.blue(), rc::blue(expected), tolerance);
}

// Light pixels (text) in a band of the picture.
int lightPixels(const QImage& image, double x0, double x1, double y0, double y1) {
    int count = 0;
    for (double y = y0; y <= y1; y += 1.0 / image.height())
        for (double x = x0; x <= x1; x += 1.0 / image.width()) count += at(image, x, y).red() > 180;
    return count;
}

}  // namespace

TEST(ColourLegendTest, TextNamesTheQuantityItsUnitsRangeAndNote) {
    rc::ColourLegend legend;
    legend.title = "radius - bit radius";
    legend.unit = "mm";
    legend.kind = rc::ColourMapKind::Diverging;
    legend.lo = -25.0;
    legend.hi = 25.0;
    legend.range = "fixed";
    const caliper3d::scenegraph::LegendText text = caliper3d::scenegraph::legendText(legend);
    EXPECT_EQ(text.title, "radius - bit radius (mm)");
    ASSERT_EQ(text.labels.size(), 3u);
    EXPECT_EQ(text.labels[0], "25 mm");
    EXPECT_EQ(text.labels[1], "0 (bit)");
    EXPECT_EQ(text.labels[2], "-25 mm");
    EXPECT_EQ(text.footer.front(), "range: fixed");
    legend.kind = rc::ColourMapKind::Sequential;
    legend.title = "GR";
    legend.unit = "gAPI";
    legend.lo = 12.5;
    legend.hi = 140.25;
    legend.noValue = true;
    legend.note = "gamma ray";
    const caliper3d::scenegraph::LegendText gr = caliper3d::scenegraph::legendText(legend);
    EXPECT_EQ(gr.labels[0], "140 gAPI");
    EXPECT_EQ(gr.labels[1], "76.4 gAPI");
    EXPECT_EQ(gr.labels[2], "12.5 gAPI");
    EXPECT_NE(std::find(gr.footer.begin(), gr.footer.end(), "gamma ray"), gr.footer.end());
    EXPECT_NE(std::find(gr.footer.begin(), gr.footer.end(), "dark grey: no value"),
              gr.footer.end());
}

TEST(ColourLegendTest, EveryRenderedPictureCarriesTheLegendInTheMapsColours) {
    const auto png = caliper3d::test::scratch("colour_departure.png").string();
    std::filesystem::remove(png);
    const CommandRun r =
        run("render " + washoutLog() + " -o " + png + " --width 640 --height 480 --exaggerate 40");
    ASSERT_EQ(r.status, 0) << r.output;
    const QImage image(QString::fromStdString(png));
    ASSERT_FALSE(image.isNull());
    // The bar: +25 mm at its top, the bit size (grey) half-way, -25 mm at its bottom.
    expectColour(at(image, 0.92, 0.54), rc::divergingColour(0.99), 12);
    expectColour(at(image, 0.92, 0.05), rc::divergingColour(0.5), 8);
    expectColour(at(image, 0.92, -0.44), rc::divergingColour(0.01), 12);
    // Its title and labels are drawn (light text on the dark panel).
    EXPECT_GT(lightPixels(image, 0.56, 0.97, 0.6, 0.68), 40);  // title
    EXPECT_GT(lightPixels(image, 0.7, 0.885, 0.5, 0.58), 15);  // "25 mm"
}

TEST(ColourLegendTest, ColourByClassDrawsTheClassesSwatches) {
    const auto png = caliper3d::test::scratch("colour_class.png").string();
    const CommandRun r = run("render " + washoutLog() + " -o " + png +
                             " --width 640 --height 480 --exaggerate 40 --colour-by class");
    ASSERT_EQ(r.status, 0) << r.output;
    const QImage image(QString::fromStdString(png));
    ASSERT_FALSE(image.isNull());
    // Five swatches down the bar, in the report's order: in gauge ... keyseat.
    const double top = 0.55, step = 1.0 / 5;
    const std::uint32_t colours[] = {0xC8C8C8FFu, 0x0072B2FFu, 0xD55E00FFu, 0xE69F00FFu,
                                     0xCC79A7FFu};
    for (int i = 0; i < 5; ++i)
        expectColour(at(image, 0.92, top - step * i - step * 0.4), colours[i]);
    // And the washout itself is drawn in the washout's colour somewhere in the picture.
    int vermillion = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width() / 2 + 100; ++x) {
            const QColor c = image.pixelColor(x, y);
            vermillion += c.red() > 150 && c.green() > 40 && c.green() < 110 && c.blue() < 40;
        }
    EXPECT_GT(vermillion, 20);
}

TEST(ColourLegendTest, ColourOptionsAreCheckedAndAnUnknownNameListsTheValidOnes) {
    const auto png = caliper3d::test::scratch("colour_bad.png").string();
    CommandRun r = run("render " + washoutLog() + " -o " + png + " --colour-by porosity");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("cannot colour by 'porosity'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("departure, diameter, ellipticity, class, dls"), std::string::npos)
        << r.output;
    r = run("render " + washoutLog() + " -o " + png + " --colour-range 5,1");
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("--colour-range"), std::string::npos) << r.output;
    r = run("render " + washoutLog() + " -o " + png + " --colour-range 5,10");
    EXPECT_EQ(r.status, 1) << r.output;  // a departure range must hold the bit size
    EXPECT_NE(r.output.find("LO must be below 0"), std::string::npos) << r.output;
    r = run("export " + washoutLog() + " -o " + caliper3d::test::scratch("colour.iv").string() +
            " --colour-by diameter");
    EXPECT_EQ(r.status, 0) << r.output;
}

TEST(ColourLegendTest, EveryLineLiesOnTheLegendsPanelInANarrowPicture) {
    // 300 pixels across: the title "radius - bit radius (mm)" and the notes are wider than a
    // fixed share of the picture would be. Looking down from the top, the well is a dot in
    // the middle, under the panel.
    const auto png = caliper3d::test::scratch("colour_narrow.png").string();
    const CommandRun r = run("render " + washoutLog() + " -o " + png +
                             " --width 300 --height 800 --view top --exaggerate 1");
    ASSERT_EQ(r.status, 0) << r.output;
    const QImage image(QString::fromStdString(png));
    ASSERT_FALSE(image.isNull());
    const QColor panel(0x26, 0x2B, 0x36);
    const auto isPanel = [&](int x, int y) {
        const QColor c = image.pixelColor(x, y);
        return std::abs(c.red() - panel.red()) <= 2 && std::abs(c.green() - panel.green()) <= 2 &&
               std::abs(c.blue() - panel.blue()) <= 2;
    };
    // The panel's rows at the right edge: from the middle of its bar (the picture's middle)
    // up to its top and down to below the last note.
    int top = image.height() / 2;
    ASSERT_TRUE(isPanel(image.width() - 2, top)) << "the panel at the bar's middle";
    while (top > 0 && isPanel(image.width() - 2, top - 1)) --top;
    top += 2;
    int bottom = top;
    while (bottom + 1 < image.height() && isPanel(image.width() - 2, bottom + 1)) ++bottom;
    ASSERT_GT(bottom - top, image.height() / 3) << "the panel runs down the right edge";
    int left = image.width() - 2;
    while (left > 0 && isPanel(left - 1, top)) --left;
    EXPECT_GT(image.width() - left, 120) << "as wide as its title, whatever the picture's width";
    EXPECT_LT(image.width() - left, 240);
    // Nothing of the legend's text left of its panel: no light pixel in the 40 columns there
    // (above the north arrow, in the bottom-left 124 pixels).
    ASSERT_LT(bottom, image.height() - 124);
    int outside = 0;
    for (int y = top; y <= bottom; ++y)
        for (int x = std::max(0, left - 40); x < left; ++x)
            outside += image.pixelColor(x, y).lightness() > 150;
    EXPECT_EQ(outside, 0);
}

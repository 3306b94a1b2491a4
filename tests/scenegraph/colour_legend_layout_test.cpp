// Where the colour legend is drawn: its panel's box (what labels keep clear of) is where its
// fill is, and a legend with long notes stays inside a narrow, tall view (the window's).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include <gtest/gtest.h>

#include <Inventor/nodes/SoSeparator.h>

#include "coin_fixture.h"
#include "reconstruction/mesh/wall_colouring.h"
#include "scenegraph/camera_setup.h"
#include "scenegraph/colour_legend.h"
#include "scenegraph/label_style.h"
#include "scenegraph/node_ref.h"
#include "scenegraph/offscreen_renderer.h"

namespace caliper3d::scenegraph {
namespace {

// The legend of a colouring by change between two runs: a long range and note, and three
// lines saying what is not compared (reconstruction/analysis/run_change.cpp).
reconstruction::ColourLegend changeLikeLegend() {
    reconstruction::ColourLegend legend;
    legend.title = "r1.las minus r2.las";
    legend.unit = "mm";
    legend.kind = reconstruction::ColourMapKind::Diverging;
    legend.lo = -5.0;
    legend.hi = 5.0;
    legend.range = "98th pct, at least 1.5 mm, over all 2 wells";
    legend.centre = "no change";
    legend.note = "wall movement at each azimuth, shift +0.350 m";
    legend.noValue = true;
    legend.noValueText = "not compared:\nno overlap, no data,\narms not open, cased";
    return legend;
}

// The box of the pixels drawn in the panel's fill (0x262B36), and how many there are.
struct Fill {
    ScreenBox box{1e9f, 1e9f, -1e9f, -1e9f};
    int pixels = 0;
};
Fill panelFill(const RenderedImage& image) {
    Fill fill;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = &image.rgba[(std::size_t(y) * image.width + x) * 4];
            if (std::abs(p[0] - 0x26) > 2 || std::abs(p[1] - 0x2B) > 2 || std::abs(p[2] - 0x36) > 2)
                continue;
            ++fill.pixels;
            fill.box.x0 = std::min(fill.box.x0, float(x));
            fill.box.y0 = std::min(fill.box.y0, float(y));
            fill.box.x1 = std::max(fill.box.x1, float(x + 1));
            fill.box.y1 = std::max(fill.box.y1, float(y + 1));
        }
    return fill;
}

class ColourLegendLayoutTest : public CoinTest {};

TEST_F(ColourLegendLayoutTest, ALongLegendStaysInsideANarrowTallViewWhereItsBoxSays) {
    // The window's view beside its docks on a 1440 x 900 screen, the legend in its lower half.
    const int width = 490, height = 785;
    const reconstruction::ColourLegend legend = changeLikeLegend();
    auto root = makeRef(new SoSeparator);
    root->addChild(makeColourLegend(legend, height, kLowerLegendBar));
    RenderedImage image;
    try {
        OffscreenRenderer renderer;
        image = renderer.render(root.get(), width, height, kBackgroundColour);
    } catch (const std::runtime_error& e) {
        GTEST_SKIP() << "no offscreen context: " << e.what();
    }
    const ScreenBox box = legendPanel_px(legend, width, height, kLowerLegendBar);
    const Fill fill = panelFill(image);
    ASSERT_GT(fill.pixels, 1000);
    // The box is the fill's, to a pixel.
    EXPECT_NEAR(fill.box.x0, box.x0, 1.5f);
    EXPECT_NEAR(fill.box.y0, box.y0, 1.5f);
    EXPECT_NEAR(fill.box.x1, box.x1, 1.5f);
    EXPECT_NEAR(fill.box.y1, box.y1, 1.5f);
    // Its last note ends inside the view, and it leaves nearly half the view's width to the
    // well: its notes are wrapped to no wider than its title (unwrapped, the note alone made
    // it 360 px wide).
    EXPECT_LE(box.y1, float(height));
    EXPECT_LT(box.width(), 0.55f * float(width));
    // No text of the legend outside its panel: every light pixel lies in the box.
    int outside = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = &image.rgba[(std::size_t(y) * image.width + x) * 4];
            const bool light = p[0] > 150 && p[1] > 150 && p[2] > 150;
            const bool in = x >= box.x0 - 1 && x < box.x1 + 1 && y >= box.y0 - 1 && y < box.y1 + 1;
            outside += light && !in ? 1 : 0;
        }
    EXPECT_EQ(outside, 0);
}

// Up, the legend's text is laid out in pixels and the window's bar is no taller than its most:
// a taller view gives a panel as tall in pixels, where a fraction of the height would have
// spread the notes apart.
TEST_F(ColourLegendLayoutTest, ATallerViewGivesTheSamePanelInPixels) {
    const reconstruction::ColourLegend legend = changeLikeLegend();
    const ScreenBox short785 = legendPanel_px(legend, 490, 785, kLowerLegendBar);
    const ScreenBox tall1400 = legendPanel_px(legend, 490, 1400, kLowerLegendBar);
    EXPECT_NEAR(short785.height(), tall1400.height(), 0.5f);
    EXPECT_LE(tall1400.y1, 1400.0f);
    // Its notes wrapped at the title's length in characters: the panel about the title's
    // width (13 px text, 10 px from the edge, 10 px margin; characters differ in width by a
    // few pixels a line), not the width of 30 characters.
    const float title = std::ceil(textWidth_px("r1.las minus r2.las (mm)", 13.0f) + 20.0f);
    EXPECT_LE(short785.width(), 1.05f * title);
    // The bar (at most 200 px), the title above it and nine note lines below it.
    EXPECT_LT(short785.height(), 0.55f * 785.0f);
    EXPECT_LE(short785.y1, 785.0f);
    // A picture's default bar keeps its share of the height; its notes stay as close.
    const ScreenBox picture800 = legendPanel_px(legend, 490, 800);
    const ScreenBox picture1600 = legendPanel_px(legend, 490, 1600);
    EXPECT_NEAR(picture1600.height() - picture800.height(), 0.5f * 800.0f, 1.0f);
}

}  // namespace
}  // namespace caliper3d::scenegraph

#pragma once

#include <string>
#include <vector>

#include "reconstruction/mesh/wall_colouring.h"
#include "scenegraph/label_placement.h"

class SoSeparator;

namespace caliper3d::scenegraph {

// The lines of text a legend shows, top to bottom beside its colour bar: the title with its
// unit, the values at the bar's ends and centre (or the class names), where the range comes
// from and the note. Plain strings, so tests read them without drawing.
struct LegendText {
    std::string title;
    std::vector<std::string> labels;  // continuous: hi, centre, lo; categorical: one a class
    std::vector<std::string> footer;  // range source, note, "no value" when some lack one
};
LegendText legendText(const reconstruction::ColourLegend& legend);

// An overlay drawing `legend` at the right edge of a picture `height` pixels tall, over
// whatever the scene draws there: its own orthographic camera spanning the viewport, no depth
// test (SoAnnotation), unlit colours and SoText2 labels. Across, it is laid out in pixels from
// the right edge, its panel as wide as its longest line (legendWidth_px); up, its bar in
// fractions of the picture's height and its text in pixels from the bar (a view that changes
// height makes it again). Add it after the scene under the render root, or as a viewer's
// superimposition; it adds nothing to a bounding box of the scene. Main thread only.
// Where its colour bar runs, up the picture ([-1, 1]), and how long it may be at most (pixels;
// 0: no limit, it keeps its bottom); the title above it, the notes below (wrapped at the
// title's length, 20 to 30 characters; the bar is raised, and shortened if need be, until the last
// note ends inside the picture). A window's tall view whose wells are named at their top puts it in
// its lower half, no taller than the room it needs.
struct LegendBar {
    float top = 0.55f;
    float bottom = -0.45f;
    float maxLength_px = 0.0f;
};
constexpr LegendBar kLowerLegendBar{-0.15f, -0.7f, 200.0f};
SoSeparator* makeColourLegend(const reconstruction::ColourLegend& legend, int height,
                              LegendBar bar = {});

// The width of the legend's panel, pixels from the picture's right edge: the room a view
// leaves it when it frames the scene beside it.
float legendWidth_px(const reconstruction::ColourLegend& legend);
// The legend's panel in a picture `width` x `height` pixels (from its top-left corner): what
// labels keep clear of.
ScreenBox legendPanel_px(const reconstruction::ColourLegend& legend, int width, int height,
                         LegendBar bar = {});

// A number as legends print it: 3 significant digits, no trailing zeros ("-25", "0.25",
// "1.12", "216").
std::string legendNumber(double value);

}  // namespace caliper3d::scenegraph

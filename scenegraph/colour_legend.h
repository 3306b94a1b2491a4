#pragma once

#include <string>
#include <vector>

#include "reconstruction/mesh/wall_colouring.h"

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

// An overlay drawing `legend` at the right edge of the picture, over whatever the scene
// draws there: its own orthographic camera spanning the viewport, no depth test
// (SoAnnotation), unlit colours and SoText2 labels. Add it after the scene under the render
// root, or as a viewer's superimposition; it adds nothing to a bounding box of the scene.
// Main thread only.
SoSeparator* makeColourLegend(const reconstruction::ColourLegend& legend);

// A number as legends print it: 3 significant digits, no trailing zeros ("-25", "0.25",
// "1.12", "216").
std::string legendNumber(double value);

}  // namespace caliper3d::scenegraph

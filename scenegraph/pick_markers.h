#pragma once

#include <vector>

#include "io/picks_reader.h"
#include "reconstruction/well_geometry.h"

class SoSeparator;

namespace caliper3d::scenegraph {

// Image-log picks on the wall (`--picks`): for each pick within the log, a line along the wall
// over its depths at its azimuth, and for a breakout the opposite side too (a breakout's two
// sides are one direction), standing a little off the widest arm so the wall never hides it.
// Magenta, the colour no wall colour map uses. Main thread only.
// `radialExaggeration`: the radii as drawn.
SoSeparator* makePickMarkers(const reconstruction::WellGeometry& geometry,
                             const std::vector<io::Pick>& picks, double radialExaggeration);

// The point on the wall of row `row` at `azimuth_deg` (clockwise from north in the section
// plane), `radius_mm` from the tool axis, in the analysis frame (metres).
reconstruction::Ned wallPointAt(const reconstruction::WellGeometry& geometry, std::size_t row,
                                double azimuth_deg, double radius_mm);

}  // namespace caliper3d::scenegraph

#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

// A point of a well's path at a given measured depth.
struct PathSample {
    double md = 0.0;
    Ned position{0.0};  // analysis frame (north, east, TVD down), wellhead offset included
    double inc_deg = 0.0;
    double azi_deg = 0.0;
};

// Where the path of `geometry` is at measured depth `md_m`, for 0 <= md_m <= the last row's
// depth (clamped to that range):
//  - within the logged rows, on the straight line between the centres of the two rows around
//    it (rows lie millimetres to centimetres apart), inclination and azimuth of the deeper;
//  - above the first row, on the path from the wellhead (MD 0) that the geometry ties the
//    log to (docs/conventions.md, "Tie-in"): the minimum-curvature arc from the vertical
//    station at the surface to the first row, or the survey's arcs when one gives the path.
// The part above the first row is known only for a geometry that starts at its log's top
// (GeometryOptions::continueFrom unset); a stretch's gives the first row's point there.
PathSample pathAt(const WellGeometry& geometry, double md_m);

// The path above the logged interval, from the wellhead (MD 0) down to the first row, as a
// line to draw: scene-frame points about `spacing_m` apart, both ends included. Empty when
// the log starts at (or above) MD 0 or the geometry is a stretch of a longer log.
std::vector<glm::vec3> unloggedPathLine(const WellGeometry& geometry, double spacing_m);

}  // namespace caliper3d::reconstruction

#pragma once

#include <cmath>
#include <cstddef>

#include <glm/vec3.hpp>

namespace caliper3d::reconstruction {

class WellGeometry;

// A point of the drawn wall traced back to the section it shows and its direction around that
// section (docs/conventions.md, "Angle around a section"). Every figure is the true geometry's,
// whatever level of detail or radial exaggeration drew the point.
struct WallPoint {
    std::size_t row = 0;  // the section (row of the table) whose plane passes nearest the point
    // Distance from that section's plane along the hole axis, metres (positive deeper).
    double fromPlane_m = 0.0;
    // Clockwise from arm 1 looking down the hole, about the tool axis, [0, 360).
    double fromArm1_deg = 0.0;
    // Clockwise from the high side looking down the hole (north in a vertical hole), [0, 360);
    // NaN on an inclined row whose hole azimuth is unknown and whose arm 1 came from P1AZ.
    double fromHighSide_deg = std::nan("");
    // Azimuth of the direction's horizontal projection, [0, 360); NaN within 0.06 deg of
    // vertical, and on an inclined row whose hole azimuth is unknown and whose arm 1 came
    // from RB (the rule the report applies to its own azimuths).
    double azimuth_deg = std::nan("");
    // The section's closed spline at that angle: tool axis to the true wall, millimetres
    // (NaN for a section without data).
    double radius_mm = std::nan("");
};

// The wall point at `scenePoint` (scene frame, as drawn) among rows [firstRow, lastRow] (a
// segment's rows): the row whose section plane the point lies nearest to, found where the
// signed distance to the planes changes sign (a ring is drawn in its row's plane, so a point
// of a strip between two kept rows lies between their planes at every level of detail), then
// the direction from that row's tool axis in its frame. With a radial exaggeration F the
// point is first brought back to the true wall: sections are drawn F times larger about the
// centroid of their area, so the true point is centroid + (drawn - centroid) / F (to the
// drawn level's shape error).
WallPoint locateWallPoint(const WellGeometry& geometry, std::size_t firstRow, std::size_t lastRow,
                          const glm::dvec3& scenePoint);

}  // namespace caliper3d::reconstruction

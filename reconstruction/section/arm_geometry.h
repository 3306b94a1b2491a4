#pragma once

#include <vector>

#include <glm/vec2.hpp>

namespace caliper3d::reconstruction {

// Arms are evenly spaced and numbered clockwise seen looking down the hole.
// Arm k (1-based) of n lies (k-1)*360/n degrees clockwise from arm 1.
double armClockwiseAngle_deg(int arm, int armCount);

// The same direction as a "tool angle": counter-clockwise from arm 1 in the
// tool frame (X on arm 1, Y = X cross hole axis), in [0, 360). For six arms
// this is the reference's table 0, 300, 240, 180, 120, 60.
double armToolAngle_deg(int arm, int armCount);

// Pad points in the tool frame (millimetres): radius r_k along tool angle of arm k.
std::vector<glm::dvec2> armPoints(const double* radii_mm, int armCount);

// Wraps an angle into [0, 360).
double wrap360(double angle_deg);

}  // namespace caliper3d::reconstruction

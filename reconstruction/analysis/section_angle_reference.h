#pragma once

#include <cstddef>

#include "reconstruction/section/section_frame.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

// What the angles around a section are counted from, clockwise looking down the hole, in the
// section plane (docs/architecture.md, "Section inspector"):
//   North     the in-plane direction whose horizontal projection points north (as arm 1 is
//             placed from P1AZ); in a vertical hole, north itself.
//   HighSide  the high side of the hole (the upward direction in the plane); north in a
//             vertical hole.
// Both are rigid rotations of the plane, so a shape keeps its true outline whichever is used.
enum class AngleReference : unsigned char { North, HighSide };

// The reference direction of a section whose hole tangent is `tangent` (unit, analysis frame).
// North falls back to the high side in a horizontal hole, where no in-plane direction points
// north seen from above.
Ned referenceDirection(const Ned& tangent, AngleReference reference);

// Clockwise angle (degrees, [0, 360)) from `reference` to arm 1 of `frame`: an angle phi from
// arm 1 is at phi + this from the reference.
double arm1Angle_deg(const SectionFrame& frame, AngleReference reference);

// Clockwise angle (degrees, [0, 360)) of the in-plane direction `d` from `reference`; NaN when
// `d` has (almost) no component in the plane.
double angleFromReference_deg(const SectionFrame& frame, const Ned& d, AngleReference reference);

// Whether `reference` is known on `row`: always, unless the hole is inclined and its azimuth
// unknown (docs/conventions.md, "Hole azimuth"); then arm 1 placed from RB has a high side but
// no north, and arm 1 placed from P1AZ (or taken as north) a north but no high side, as the
// report leaves the major axis's azimuth or its angle from the high side empty.
bool referenceKnown(const WellGeometry& geometry, std::size_t row, AngleReference reference);

}  // namespace caliper3d::reconstruction

#pragma once

#include <glm/vec3.hpp>

#include "reconstruction/path/hole_direction.h"

namespace caliper3d::reconstruction {

// Vectors in the analysis frame: x = north, y = east, z = down (TVD), metres.
using Ned = glm::dvec3;

// Unit vector along the hole, pointing deeper.
Ned holeTangent(double inc_deg, double azi_deg);
Ned holeTangent(const HoleDirection& d);

// Unit vector in the section plane pointing to the high side of the hole
// (the upward direction projected on the plane). Undefined in a vertical hole,
// where north is returned.
Ned highSide(double inc_deg, double azi_deg);
Ned highSide(const HoleDirection& d);

// Orthonormal frame of a section: the plane is perpendicular to `tangent`;
// `arm1` is arm 1's direction; `side` = tangent x arm1 is 90 degrees clockwise
// from arm 1 seen looking down the hole. A point at clockwise angle phi from
// arm 1 and radius r is centre + r (cos phi arm1 + sin phi side).
struct SectionFrame {
    Ned tangent{0.0, 0.0, 1.0};
    Ned arm1{1.0, 0.0, 0.0};
    Ned side{0.0, 1.0, 0.0};

    Ned direction(double clockwiseAngle_rad) const;
};

// Arm 1 is the unit vector in the section plane whose horizontal projection
// points at azimuth p1az. Falls back to the relative bearing 0 (high side)
// when the hole is so steep that the projection is degenerate.
SectionFrame frameFromPadAzimuth(double inc_deg, double azi_deg, double p1az_deg);
SectionFrame frameFromPadAzimuth(const HoleDirection& d, double p1az_deg);

// Arm 1 is rb degrees clockwise (looking down the hole) from the high side.
SectionFrame frameFromRelativeBearing(double inc_deg, double azi_deg, double rb_deg);
SectionFrame frameFromRelativeBearing(const HoleDirection& d, double rb_deg);

// The scene (Coin, Y up) frame is x = east, y = up, z = south. This is the
// one place where analysis-frame vectors become scene vectors.
inline glm::dvec3 toScene(const Ned& v) {
    return {v.y, -v.z, -v.x};
}
// Its inverse: a scene point or direction back in the analysis frame (picking).
inline Ned fromScene(const glm::dvec3& v) {
    return {-v.z, v.x, -v.y};
}

}  // namespace caliper3d::reconstruction

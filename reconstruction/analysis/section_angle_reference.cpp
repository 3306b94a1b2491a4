#include "reconstruction/analysis/section_angle_reference.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "reconstruction/section/arm_geometry.h"

namespace caliper3d::reconstruction {

namespace {

// The high side from the tangent alone (as the report's world angles take it): (t_z t_x,
// t_z t_y, -(t_x^2 + t_y^2)), normalised; north in a vertical hole.
Ned highSideOf(const Ned& t) {
    const double horizontal2 = t.x * t.x + t.y * t.y;
    if (horizontal2 < 1e-24) return {1.0, 0.0, 0.0};
    return glm::normalize(Ned(t.z * t.x, t.z * t.y, -horizontal2));
}

}  // namespace

Ned referenceDirection(const Ned& tangent, AngleReference reference) {
    if (reference == AngleReference::HighSide || std::abs(tangent.z) < 1e-6)
        return highSideOf(tangent);
    // North moved into the plane along the vertical: (1, 0, s) with (1, 0, s) . t = 0, as
    // frameFromPadAzimuth places arm 1 at P1AZ 0.
    return glm::normalize(Ned(1.0, 0.0, -tangent.x / tangent.z));
}

double angleFromReference_deg(const SectionFrame& frame, const Ned& d, AngleReference reference) {
    const Ned r = referenceDirection(frame.tangent, reference);
    // 90 degrees clockwise from the reference looking down the hole (as the frame's `side`).
    const Ned right = glm::cross(frame.tangent, r);
    const double x = glm::dot(d, r), y = glm::dot(d, right);
    if (std::hypot(x, y) < 1e-9) return std::nan("");
    return wrap360(glm::degrees(std::atan2(y, x)));
}

double arm1Angle_deg(const SectionFrame& frame, AngleReference reference) {
    return angleFromReference_deg(frame, frame.arm1, reference);
}

bool referenceKnown(const WellGeometry& g, std::size_t row, AngleReference reference) {
    if (g.orientation(row) == WellGeometry::Orientation::Unoriented) return false;
    if (g.holeAzimuthKnown() || !(g.path()[row].inc_deg > 0.0)) return true;
    const bool fromRelativeBearing =
        g.orientation(row) == WellGeometry::Orientation::RelativeBearing;
    return (reference == AngleReference::HighSide) == fromRelativeBearing;
}

}  // namespace caliper3d::reconstruction

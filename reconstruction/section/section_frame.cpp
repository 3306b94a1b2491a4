#include "reconstruction/section/section_frame.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

namespace caliper3d::reconstruction {

Ned holeTangent(double inc_deg, double azi_deg) {
    return holeTangent(HoleDirection(inc_deg, azi_deg));
}

Ned holeTangent(const HoleDirection& d) {
    return {d.sinInc * d.cosAzi, d.sinInc * d.sinAzi, d.cosInc};
}

Ned highSide(double inc_deg, double azi_deg) {
    return highSide(HoleDirection(inc_deg, azi_deg));
}

Ned highSide(const HoleDirection& d) {
    if (std::abs(d.sinInc) < 1e-12) return {1.0, 0.0, 0.0};
    return {d.cosInc * d.cosAzi, d.cosInc * d.sinAzi, -d.sinInc};
}

Ned SectionFrame::direction(double clockwiseAngle_rad) const {
    return std::cos(clockwiseAngle_rad) * arm1 + std::sin(clockwiseAngle_rad) * side;
}

SectionFrame frameFromPadAzimuth(double inc_deg, double azi_deg, double p1az_deg) {
    return frameFromPadAzimuth(HoleDirection(inc_deg, azi_deg), p1az_deg);
}

SectionFrame frameFromPadAzimuth(const HoleDirection& d, double p1az_deg) {
    SectionFrame f;
    f.tangent = holeTangent(d);
    const double p = glm::radians(p1az_deg);
    const Ned horizontal{std::cos(p), std::sin(p), 0.0};
    // Arm 1 = horizontal direction moved into the plane along the tangent:
    // u = h + s t with u . t = 0; its horizontal projection keeps azimuth p1az
    // (for a hole that is not horizontal).
    const Ned t = f.tangent;
    if (std::abs(t.z) < 1e-6) return frameFromRelativeBearing(d, 0.0);
    const double s = -glm::dot(horizontal, t) / t.z;
    Ned u = horizontal + Ned(0.0, 0.0, s);
    u = glm::normalize(u);
    f.arm1 = u;
    f.side = glm::cross(t, u);
    return f;
}

SectionFrame frameFromRelativeBearing(double inc_deg, double azi_deg, double rb_deg) {
    return frameFromRelativeBearing(HoleDirection(inc_deg, azi_deg), rb_deg);
}

SectionFrame frameFromRelativeBearing(const HoleDirection& d, double rb_deg) {
    SectionFrame f;
    f.tangent = holeTangent(d);
    const Ned hs = highSide(d);
    const Ned right = glm::cross(f.tangent, hs);
    const double r = glm::radians(rb_deg);
    f.arm1 = std::cos(r) * hs + std::sin(r) * right;
    f.side = glm::cross(f.tangent, f.arm1);
    return f;
}

}  // namespace caliper3d::reconstruction

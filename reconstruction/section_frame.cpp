#include "reconstruction/section_frame.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

namespace caliper3d::reconstruction {

Ned holeTangent(double inc_deg, double azi_deg) {
    const double i = glm::radians(inc_deg), a = glm::radians(azi_deg);
    return {std::sin(i) * std::cos(a), std::sin(i) * std::sin(a), std::cos(i)};
}

Ned highSide(double inc_deg, double azi_deg) {
    const double i = glm::radians(inc_deg), a = glm::radians(azi_deg);
    if (std::abs(std::sin(i)) < 1e-12) return {1.0, 0.0, 0.0};
    return {std::cos(i) * std::cos(a), std::cos(i) * std::sin(a), -std::sin(i)};
}

Ned SectionFrame::direction(double clockwiseAngle_rad) const {
    return std::cos(clockwiseAngle_rad) * arm1 + std::sin(clockwiseAngle_rad) * side;
}

SectionFrame frameFromPadAzimuth(double inc_deg, double azi_deg, double p1az_deg) {
    SectionFrame f;
    f.tangent = holeTangent(inc_deg, azi_deg);
    const double p = glm::radians(p1az_deg);
    const Ned horizontal{std::cos(p), std::sin(p), 0.0};
    // Arm 1 = horizontal direction moved into the plane along the tangent:
    // u = h + s t with u . t = 0; its horizontal projection keeps azimuth p1az
    // (for a hole that is not horizontal).
    const Ned t = f.tangent;
    if (std::abs(t.z) < 1e-6) return frameFromRelativeBearing(inc_deg, azi_deg, 0.0);
    const double s = -glm::dot(horizontal, t) / t.z;
    Ned u = horizontal + Ned(0.0, 0.0, s);
    u = glm::normalize(u);
    f.arm1 = u;
    f.side = glm::cross(t, u);
    return f;
}

SectionFrame frameFromRelativeBearing(double inc_deg, double azi_deg, double rb_deg) {
    SectionFrame f;
    f.tangent = holeTangent(inc_deg, azi_deg);
    const Ned hs = highSide(inc_deg, azi_deg);
    const Ned right = glm::cross(f.tangent, hs);
    const double r = glm::radians(rb_deg);
    f.arm1 = std::cos(r) * hs + std::sin(r) * right;
    f.side = glm::cross(f.tangent, f.arm1);
    return f;
}

}  // namespace caliper3d::reconstruction

#pragma once

#include <cmath>

#include <glm/trigonometric.hpp>

namespace caliper3d::reconstruction {

// Sines and cosines of a hole direction (inclination from vertical, azimuth
// clockwise from north), computed once per section and shared by the
// minimum-curvature step, the hole tangent, the high side and the section
// frame, which would otherwise each take them again. The values are exactly
// those std::sin and std::cos give, so every formula built on them is
// bit-identical to the same formula evaluated from the angles.
struct HoleDirection {
    double inc_deg = 0.0;
    double azi_deg = 0.0;
    double sinInc = 0.0, cosInc = 1.0;
    double sinAzi = 0.0, cosAzi = 1.0;

    HoleDirection() = default;
    HoleDirection(double inc, double azi) { set(inc, azi); }

    void set(double inc, double azi) {
        inc_deg = inc;
        azi_deg = azi;
        sinInc = std::sin(glm::radians(inc));
        cosInc = std::cos(glm::radians(inc));
        sinAzi = std::sin(glm::radians(azi));
        cosAzi = std::cos(glm::radians(azi));
    }

    // Moves to the next section's direction, keeping the sine and cosine of an
    // angle that has not changed: tools sample DEVI and HAZI coarser than the
    // caliper, and holes hold their inclination or azimuth over long runs.
    void update(double inc, double azi) {
        if (!same(inc, inc_deg)) {
            inc_deg = inc;
            sinInc = std::sin(glm::radians(inc));
            cosInc = std::cos(glm::radians(inc));
        }
        if (!same(azi, azi_deg)) {
            azi_deg = azi;
            sinAzi = std::sin(glm::radians(azi));
            cosAzi = std::cos(glm::radians(azi));
        }
    }

private:
    // Equal including the sign of zero (sin(-0) is -0); NaN never equals.
    static bool same(double a, double b) { return a == b && std::signbit(a) == std::signbit(b); }
};

}  // namespace caliper3d::reconstruction

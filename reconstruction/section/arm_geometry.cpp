#include "reconstruction/section/arm_geometry.h"

#include <cmath>

#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

namespace caliper3d::reconstruction {

double wrap360(double angle_deg) {
    double a = std::fmod(angle_deg, 360.0);
    if (a < 0) a += 360.0;
    if (a >= 360.0) a -= 360.0;
    return a;
}

double armClockwiseAngle_deg(int arm, int armCount) {
    return 360.0 * (arm - 1) / armCount;
}

double armToolAngle_deg(int arm, int armCount) {
    return wrap360(-armClockwiseAngle_deg(arm, armCount));
}

std::vector<glm::dvec2> armPoints(const double* radii_mm, int armCount) {
    std::vector<glm::dvec2> points(static_cast<std::size_t>(armCount));
    for (int k = 0; k < armCount; ++k) {
        const double a = glm::radians(armToolAngle_deg(k + 1, armCount));
        points[static_cast<std::size_t>(k)] = radii_mm[k] * glm::dvec2(std::cos(a), std::sin(a));
    }
    return points;
}

}  // namespace caliper3d::reconstruction

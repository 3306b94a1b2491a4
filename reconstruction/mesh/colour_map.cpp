#include "reconstruction/mesh/colour_map.h"

#include <algorithm>
#include <cmath>

namespace caliper3d::reconstruction {

namespace {
std::uint32_t pack(double r, double g, double b) {
    auto c = [](double v) {
        return static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
    };
    return (c(r) << 24) | (c(g) << 16) | (c(b) << 8) | 0xFFu;
}
double mix(double a, double b, double t) {
    return a + (b - a) * t;
}
}  // namespace

std::uint32_t gaugeColour(double radius_mm, double bitRadius_mm) {
    const double kGrey = 0.72;
    if (!std::isfinite(radius_mm) || !std::isfinite(bitRadius_mm)) return pack(kGrey, kGrey, kGrey);
    const double d = radius_mm - bitRadius_mm;
    if (d < -3.0) {
        const double t = std::clamp((-d - 3.0) / 10.0, 0.0, 1.0);
        return pack(mix(kGrey, 0.15, t), mix(kGrey, 0.35, t), mix(kGrey, 0.95, t));
    }
    if (d <= 3.0) return pack(kGrey, kGrey, kGrey);
    const double t = std::clamp((d - 3.0) / 22.0, 0.0, 1.0);
    if (t < 0.5) {
        const double u = t * 2.0;
        return pack(mix(kGrey, 0.98, u), mix(kGrey, 0.85, u), mix(kGrey, 0.15, u));
    }
    const double u = (t - 0.5) * 2.0;
    return pack(mix(0.98, 0.85, u), mix(0.85, 0.1, u), mix(0.15, 0.05, u));
}

}  // namespace caliper3d::reconstruction

#include "reconstruction/hole_volume.h"

#include <algorithm>
#include <cmath>

#include <boost/math/constants/constants.hpp>

namespace caliper3d::reconstruction {

HoleVolume holeVolume(const std::vector<double>& md, const std::vector<double>& area,
                      const std::vector<double>& bit, const VolumeOptions& o) {
    constexpr double kPi = boost::math::constants::pi<double>();
    HoleVolume v;
    v.casingOd_mm = o.casingOd_mm;
    v.excess = o.excess;
    if (md.empty()) return v;
    v.top_m = std::max(o.top_m, md.front());
    v.bottom_m = std::min(o.bottom_m, md.back());
    const double casing_m2 = kPi / 4.0 * o.casingOd_mm * o.casingOd_mm * 1e-6;
    auto gauge = [&](std::size_t i) {
        return std::isfinite(bit[i]) ? kPi / 4.0 * bit[i] * bit[i] * 1e-6 : 0.0;
    };
    for (std::size_t i = 0; i + 1 < md.size(); ++i) {
        // The part of the step [md_i, md_i+1] inside the interval, areas interpolated linearly.
        const double a = std::max(md[i], v.top_m), b = std::min(md[i + 1], v.bottom_m);
        if (!(b > a)) continue;
        const double span = md[i + 1] - md[i];
        auto lerp = [&](double x0, double x1, double d) { return x0 + (x1 - x0) * (d - md[i]) / span; };
        const double h0 = area[i] * 1e-6, h1 = area[i + 1] * 1e-6;
        const double g0 = gauge(i), g1 = gauge(i + 1);
        const double len = b - a;
        const double hole = (lerp(h0, h1, a) + lerp(h0, h1, b)) / 2.0 * len;
        const double nominal = (lerp(g0, g1, a) + lerp(g0, g1, b)) / 2.0 * len;
        v.hole_m3 += hole;
        v.gaugeHole_m3 += nominal;
        v.annulus_m3 += std::max(0.0, hole - casing_m2 * len);
        v.gaugeAnnulus_m3 += std::max(0.0, nominal - casing_m2 * len);
    }
    v.cement_m3 = v.annulus_m3 * (1.0 + o.excess);
    v.gaugeCement_m3 = v.gaugeAnnulus_m3 * (1.0 + o.excess);
    return v;
}

}  // namespace caliper3d::reconstruction

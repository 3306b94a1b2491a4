#include "reconstruction/analysis/breakout_rose.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace caliper3d::reconstruction {

std::vector<double> BreakoutRose::mirrored() const {
    std::vector<double> all(axial_m);
    all.insert(all.end(), axial_m.begin(), axial_m.end());
    return all;
}

double BreakoutRose::largest_m() const {
    return axial_m.empty() ? 0.0 : *std::max_element(axial_m.begin(), axial_m.end());
}

BreakoutRose breakoutRose(const std::vector<Zone>& zones, double binWidth_deg) {
    const double bins = 180.0 / binWidth_deg;
    if (!(binWidth_deg > 0.0) || std::abs(bins - std::round(bins)) > 1e-9)
        throw std::invalid_argument("rose bin width must divide 180 degrees");
    BreakoutRose rose;
    rose.binWidth_deg = binWidth_deg;
    rose.axial_m.assign(static_cast<std::size_t>(std::lround(bins)), 0.0);
    for (const Zone& zone : zones) {
        if (zone.kind != BoreholeClass::Breakout || !std::isfinite(zone.meanAzimuth_deg)) continue;
        double axis_deg = std::fmod(zone.meanAzimuth_deg, 180.0);
        if (axis_deg < 0.0) axis_deg += 180.0;
        const auto bin =
            std::min(static_cast<std::size_t>(axis_deg / binWidth_deg), rose.axial_m.size() - 1);
        rose.axial_m[bin] += zone.length_m;
    }
    return rose;
}

}  // namespace caliper3d::reconstruction

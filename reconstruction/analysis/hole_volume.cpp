#include "reconstruction/analysis/hole_volume.h"

#include <algorithm>
#include <cmath>

#include <boost/math/constants/constants.hpp>

namespace caliper3d::reconstruction {

namespace {
constexpr double kPi = boost::math::constants::pi<double>();
double gaugeArea_m2(double bit_mm) {
    return std::isfinite(bit_mm) ? kPi / 4.0 * bit_mm * bit_mm * 1e-6 : 0.0;
}
}  // namespace

HoleVolumeAccumulator::HoleVolumeAccumulator(const VolumeOptions& options, double firstMd_m,
                                             double lastMd_m)
    : m_options(options) {
    m_volume.top_m = std::max(options.top_m, firstMd_m);
    m_volume.bottom_m = std::min(options.bottom_m, lastMd_m);
    m_casing_m2 = kPi / 4.0 * options.casingOd_mm * options.casingOd_mm * 1e-6;
}

void HoleVolumeAccumulator::addStep(double md0, double area0, double bit0, double md1, double area1,
                                    double bit1) {
    // The part of the step [md0, md1] inside the interval, areas interpolated linearly.
    const double a = std::max(md0, m_volume.top_m), b = std::min(md1, m_volume.bottom_m);
    if (!(b > a)) return;
    const double span = md1 - md0;
    auto lerp = [&](double x0, double x1, double d) { return x0 + (x1 - x0) * (d - md0) / span; };
    const double h0 = area0 * 1e-6, h1 = area1 * 1e-6;
    const double g0 = gaugeArea_m2(bit0), g1 = gaugeArea_m2(bit1);
    const double len = b - a;
    const double hole = (lerp(h0, h1, a) + lerp(h0, h1, b)) / 2.0 * len;
    const double nominal = (lerp(g0, g1, a) + lerp(g0, g1, b)) / 2.0 * len;
    m_volume.hole_m3 += hole;
    m_volume.gaugeHole_m3 += nominal;
    m_volume.annulus_m3 += std::max(0.0, hole - m_casing_m2 * len);
    m_volume.gaugeAnnulus_m3 += std::max(0.0, nominal - m_casing_m2 * len);
}

namespace {
// Adds [md0, md1], clipped to [top, bottom], to `gaps` (joined to the last when they touch).
void addGap(double md0, double md1, double top, double bottom,
            std::vector<std::pair<double, double>>& gaps, double& length) {
    const double a = std::max(md0, top), b = std::min(md1, bottom);
    if (!(b > a)) return;
    length += b - a;
    if (!gaps.empty() && gaps.back().second >= a)
        gaps.back().second = b;
    else
        gaps.emplace_back(a, b);
}
}  // namespace

void HoleVolumeAccumulator::addUncoveredStep(double md0, double md1) {
    addGap(md0, md1, m_volume.top_m, m_volume.bottom_m, m_volume.uncovered, m_volume.uncovered_m);
}

void HoleVolumeAccumulator::addCasedStep(double md0, double md1) {
    addGap(md0, md1, m_volume.top_m, m_volume.bottom_m, m_volume.cased, m_volume.cased_m);
}

HoleVolume HoleVolumeAccumulator::result() const {
    HoleVolume v = m_volume;
    v.casingOd_mm = m_options.casingOd_mm;
    v.excess = m_options.excess;
    v.cement_m3 = v.annulus_m3 * (1.0 + m_options.excess);
    v.gaugeCement_m3 = v.gaugeAnnulus_m3 * (1.0 + m_options.excess);
    return v;
}

}  // namespace caliper3d::reconstruction

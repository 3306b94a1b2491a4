#include "reconstruction/analysis/zone_detection.h"

#include <algorithm>
#include <cmath>

#include <glm/trigonometric.hpp>

namespace caliper3d::reconstruction {

AxialStatistics axialStatistics(const std::vector<double>& angles_deg,
                                const std::vector<double>& weights) {
    double c = 0.0, s = 0.0, w = 0.0;
    for (std::size_t i = 0; i < angles_deg.size(); ++i) {
        const double a = angles_deg[i];
        const double wi = weights.empty() ? 1.0 : weights[i];
        if (!std::isfinite(a) || !(wi > 0.0)) continue;
        c += wi * std::cos(glm::radians(2.0 * a));
        s += wi * std::sin(glm::radians(2.0 * a));
        w += wi;
    }
    AxialStatistics out;
    out.weight = w;
    if (w <= 0.0) {
        out.mean_deg = out.sd_deg = std::nan("");
        return out;
    }
    double mean = glm::degrees(std::atan2(s, c)) / 2.0;
    if (mean < 0.0) mean += 180.0;
    if (mean >= 180.0) mean -= 180.0;
    out.mean_deg = mean;
    const double r = std::min(1.0, std::hypot(c, s) / w);
    out.sd_deg = r > 0.0 ? glm::degrees(std::sqrt(std::max(0.0, -2.0 * std::log(r)))) / 2.0
                         : 90.0;  // r = 1 gives 0, not -0
    return out;
}

std::vector<Zone> detectZones(const std::vector<double>& md,
                              const std::vector<BoreholeClass>& classes,
                              const std::vector<double>& azimuth, const std::vector<double>& dmax,
                              const std::vector<double>& dmin) {
    return detectZones(
        classes, [&](std::size_t i) { return md[i]; }, [&](std::size_t i) { return azimuth[i]; },
        [&](std::size_t i) { return dmax[i]; }, [&](std::size_t i) { return dmin[i]; });
}

std::vector<Zone> detectZones(const std::vector<BoreholeClass>& classes,
                              const std::function<double(std::size_t)>& md,
                              const std::function<double(std::size_t)>& azimuth,
                              const std::function<double(std::size_t)>& dmax,
                              const std::function<double(std::size_t)>& dmin) {
    std::vector<Zone> zones;
    std::size_t i = 0;
    const std::size_t n = classes.size();
    while (i < n) {
        if (classes[i] == BoreholeClass::InGauge || classes[i] == BoreholeClass::NoData ||
            classes[i] == BoreholeClass::Cased) {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j + 1 < n && classes[j + 1] == classes[i]) ++j;
        Zone z;
        z.kind = classes[i];
        z.firstSection = i;
        z.lastSection = j;
        const double above = i > 0 ? (md(i) - md(i - 1)) / 2.0 : 0.0;
        const double below = j + 1 < n ? (md(j + 1) - md(j)) / 2.0 : 0.0;
        z.top_m = md(i) - above;
        z.bottom_m = md(j) + below;
        z.length_m = z.bottom_m - z.top_m;
        std::vector<double> angles(j - i + 1);
        for (std::size_t k = i; k <= j; ++k) angles[k - i] = azimuth(k);
        const AxialStatistics st = axialStatistics(angles);
        z.meanAzimuth_deg = st.mean_deg;
        z.circularSd_deg = st.sd_deg;
        double sMax = 0.0, sMin = 0.0;
        for (std::size_t k = i; k <= j; ++k) {
            sMax += dmax(k);
            sMin += dmin(k);
        }
        z.meanDmax_mm = sMax / static_cast<double>(j - i + 1);
        z.meanDmin_mm = sMin / static_cast<double>(j - i + 1);
        zones.push_back(z);
        i = j + 1;
    }
    return zones;
}

namespace {

// The WSM quality of summarised breakouts: the first of A to D whose zone count, combined length
// and spread they meet; E where they have no zones, no spread to measure, or meet none.
char wsmQuality(const BreakoutSummary& s, const WsmQualityRules& rules) {
    const double sd = s.circularSd_deg;
    if (s.zoneCount == 0 || !std::isfinite(sd)) return 'E';
    if (s.zoneCount >= rules.zonesA && s.combinedLength_m >= rules.lengthA_m && sd <= rules.sdA_deg)
        return 'A';
    if (s.zoneCount >= rules.zonesB && s.combinedLength_m >= rules.lengthB_m && sd <= rules.sdB_deg)
        return 'B';
    if (s.zoneCount >= rules.zonesC && s.combinedLength_m >= rules.lengthC_m && sd <= rules.sdC_deg)
        return 'C';
    if (sd <= rules.sdD_deg) return 'D';
    return 'E';
}

}  // namespace

BreakoutSummary summariseBreakouts(const std::vector<Zone>& zones, const WsmQualityRules& rules) {
    BreakoutSummary out;
    std::vector<double> angles, weights;
    for (const Zone& z : zones) {
        if (z.kind != BoreholeClass::Breakout) continue;
        ++out.zoneCount;
        out.combinedLength_m += z.length_m;
        angles.push_back(z.meanAzimuth_deg);
        weights.push_back(z.length_m);
    }
    const AxialStatistics st = axialStatistics(angles, weights);
    out.meanAzimuth_deg = st.mean_deg;
    out.circularSd_deg = st.sd_deg;
    out.shmaxAzimuth_deg =
        std::isfinite(st.mean_deg) ? std::fmod(st.mean_deg + 90.0, 180.0) : st.mean_deg;
    out.quality = wsmQuality(out, rules);
    return out;
}

}  // namespace caliper3d::reconstruction

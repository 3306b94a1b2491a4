#include "reconstruction/analysis/borehole_classifier.h"

#include <algorithm>
#include <cmath>

namespace caliper3d::reconstruction {

std::string_view className(BoreholeClass c) {
    switch (c) {
        case BoreholeClass::InGauge:
            return "in_gauge";
        case BoreholeClass::Undergauge:
            return "undergauge";
        case BoreholeClass::Washout:
            return "washout";
        case BoreholeClass::Breakout:
            return "breakout";
        case BoreholeClass::Keyseat:
            return "keyseat";
        case BoreholeClass::Cased:
            return "cased";
        case BoreholeClass::NoData:
            return "no_data";
    }
    return "in_gauge";
}

BoreholeClass classifyShape(const ClassifierInput& s, const ClassificationRules& rules) {
    const double bit = s.bit_mm;
    if (!std::isfinite(bit) || !std::isfinite(s.dmin_mm) || !std::isfinite(s.dmax_mm))
        return BoreholeClass::InGauge;
    if (s.dmax_mm < bit - rules.undergauge_mm) return BoreholeClass::Undergauge;
    if (s.dmin_mm > bit + rules.washout_mm) return BoreholeClass::Washout;
    const bool elongated = s.dmax_mm - s.dmin_mm >= rules.elongation_mm &&
                           std::abs(s.dmin_mm - bit) <= rules.breakoutMinGauge_mm;
    if (!elongated) return BoreholeClass::InGauge;
    if (s.inc_deg > rules.deviatedInclination_deg) {
        // Distance of the major axis from the high/low side line.
        const double a = std::fmod(std::fmod(s.majorFromHighSide_deg, 180.0) + 180.0, 180.0);
        const double fromLine = std::min(a, 180.0 - a);
        if (fromLine <= rules.highSideTolerance_deg) return BoreholeClass::Keyseat;
    }
    return BoreholeClass::Breakout;
}

namespace {

using Accessor = std::function<double(std::size_t)>;

// Largest tool turn over any window of `window` metres within [first, last],
// scaled up to the window for a run shorter than it.
double maxTurnPerWindow(const Accessor& mdAt, const Accessor& toolAzimuthAt, std::size_t first,
                        std::size_t last, double window) {
    std::vector<double> unwrapped;
    std::vector<double> md;
    double previous = std::nan(""), offset = 0.0;
    for (std::size_t i = first; i <= last; ++i) {
        const double a = toolAzimuthAt(i);
        if (!std::isfinite(a)) continue;
        if (std::isfinite(previous)) {
            double d = a - previous;
            if (d > 180.0)
                offset -= 360.0;
            else if (d < -180.0)
                offset += 360.0;
        }
        previous = a;
        unwrapped.push_back(a + offset);
        md.push_back(mdAt(i));
    }
    if (unwrapped.size() < 2) return 0.0;
    const double length = md.back() - md.front();
    if (length <= 0.0) return 0.0;
    if (length < window) return std::abs(unwrapped.back() - unwrapped.front()) * window / length;
    double worst = 0.0;
    std::size_t j = 0;
    for (std::size_t i = 0; i < unwrapped.size(); ++i) {
        while (j + 1 < unwrapped.size() && md[j + 1] <= md[i] + window) ++j;
        for (std::size_t k = i; k <= j; k += std::max<std::size_t>(1, (j - i) / 64))
            worst = std::max(worst, std::abs(unwrapped[k] - unwrapped[i]));
        worst = std::max(worst, std::abs(unwrapped[j] - unwrapped[i]));
    }
    return worst;
}

}  // namespace

BreakoutEvidence breakoutEvidenceFor(int arms) {
    return arms <= 4 ? BreakoutEvidence::ToolStops : BreakoutEvidence::AxisFixedInEarth;
}

void applyBreakoutZoneRules(std::vector<BoreholeClass>& out, const Accessor& md,
                            const Accessor& azimuth, const ClassificationRules& rules,
                            BreakoutEvidence evidence) {
    // An axis (modulo 180) turns by half what its doubled angle (modulo 360) turns.
    const bool axial = evidence == BreakoutEvidence::AxisFixedInEarth;
    const Accessor doubled = [&](std::size_t i) { return std::fmod(2.0 * azimuth(i), 360.0); };
    const Accessor& turning = axial ? doubled : azimuth;
    const double scale = axial ? 0.5 : 1.0;
    std::size_t i = 0;
    while (i < out.size()) {
        if (out[i] != BoreholeClass::Breakout) {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j + 1 < out.size() && out[j + 1] == BoreholeClass::Breakout) ++j;
        // A run's length counts half a sampling step beyond each end section.
        const double stepAbove = i > 0 ? md(i) - md(i - 1) : 0.0;
        const double stepBelow = j + 1 < out.size() ? md(j + 1) - md(j) : 0.0;
        const double length = md(j) - md(i) + (stepAbove + stepBelow) / 2.0;
        const bool tooShort = length < rules.minBreakoutLength_m;
        const bool rotating = scale * maxTurnPerWindow(md, turning, i, j, rules.rotationWindow_m) >=
                              rules.maxToolRotation_deg;
        if (tooShort || rotating)
            for (std::size_t k = i; k <= j; ++k) out[k] = BoreholeClass::InGauge;
        i = j + 1;
    }
}

}  // namespace caliper3d::reconstruction

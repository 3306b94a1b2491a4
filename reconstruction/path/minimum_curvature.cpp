#include "reconstruction/path/minimum_curvature.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

namespace caliper3d::reconstruction {

namespace {
double ratioFactor(double b) {
    if (std::abs(b) < 1e-4) {
        const double b2 = b * b;
        return 1.0 + b2 / 12.0 + b2 * b2 / 120.0;
    }
    return 2.0 / b * std::tan(b / 2.0);
}

// sin(x) of a half-angle step. Consecutive rows of a log 2.5 mm apart differ by thousandths of
// a degree, and std::sin took a tenth of placing a field's well (docs/benchmarks.md, "Half-angle
// sines by their series"): below 0.01 rad the series to x^7, whose next term is under 3e-22
// of x, so the result is std::sin's to a rounding.
double halfAngleSine(double x) {
    if (std::abs(x) < 1e-2) {
        const double x2 = x * x;
        return x + x * x2 * (-1.0 / 6.0 + x2 * (1.0 / 120.0 - x2 * (1.0 / 5040.0)));
    }
    return std::sin(x);
}
}  // namespace

MinimumCurvatureStep minimumCurvatureStep(const SurveyStation& a, const SurveyStation& b) {
    return minimumCurvatureStep(a.md, HoleDirection(a.inc_deg, a.azi_deg), b.md,
                                HoleDirection(b.inc_deg, b.azi_deg));
}

MinimumCurvatureStep minimumCurvatureStep(double mdA, const HoleDirection& a, double mdB,
                                          const HoleDirection& b) {
    const double i1 = glm::radians(a.inc_deg), i2 = glm::radians(b.inc_deg);
    const double a1 = glm::radians(a.azi_deg), a2 = glm::radians(b.azi_deg);
    // Dogleg from the dot product of the unit tangents, written with the
    // half-angle (haversine) form, which stays accurate for tiny angles.
    const double sinHalfI = halfAngleSine((i2 - i1) / 2.0);
    const double sinHalfA = halfAngleSine((a2 - a1) / 2.0);
    const double h = sinHalfI * sinHalfI + a.sinInc * b.sinInc * sinHalfA * sinHalfA;
    const double dogleg = 2.0 * std::asin(std::sqrt(std::clamp(h, 0.0, 1.0)));
    const double rf = ratioFactor(dogleg);
    const double half = (mdB - mdA) / 2.0 * rf;
    MinimumCurvatureStep step;
    step.dNorth = half * (a.sinInc * a.cosAzi + b.sinInc * b.cosAzi);
    step.dEast = half * (a.sinInc * a.sinAzi + b.sinInc * b.sinAzi);
    step.dTvd = half * (a.cosInc + b.cosInc);
    step.dogleg_rad = dogleg;
    return step;
}

std::vector<PathPoint> minimumCurvaturePath(const std::vector<SurveyStation>& stations) {
    std::vector<PathPoint> path;
    path.reserve(stations.size());
    HoleDirection previous, current;
    for (std::size_t i = 0; i < stations.size(); ++i) {
        PathPoint p;
        p.md = stations[i].md;
        p.inc_deg = stations[i].inc_deg;
        p.azi_deg = stations[i].azi_deg;
        if (i == 0) {
            current.set(p.inc_deg, p.azi_deg);
        } else {
            previous = current;
            current.update(p.inc_deg, p.azi_deg);
            const PathPoint& prev = path.back();
            const MinimumCurvatureStep s = minimumCurvatureStep(prev.md, previous, p.md, current);
            p.north = prev.north + s.dNorth;
            p.east = prev.east + s.dEast;
            p.tvd = prev.tvd + s.dTvd;
            p.dogleg_deg = glm::degrees(s.dogleg_rad);
            p.dls_degPer30m = doglegSeverity_degPer30m(p.dogleg_deg, p.md - prev.md);
        }
        path.push_back(p);
    }
    return path;
}

double doglegSeverity_degPer30m(double dogleg_deg, double courseLength_m) {
    if (courseLength_m <= 0.0) return 0.0;
    return dogleg_deg * 30.0 / courseLength_m;
}

}  // namespace caliper3d::reconstruction

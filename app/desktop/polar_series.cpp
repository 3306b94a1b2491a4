#include "app/desktop/polar_series.h"

#include <cmath>

#include <QtMath>

namespace caliper3d::app {

namespace {

constexpr double kOffRange_deg = 1e-3;

QPointF cartesian(const reconstruction::PolarPoint& p) {
    const double a = qDegreesToRadians(p.angle_deg);
    return {p.radius_mm * std::cos(a), p.radius_mm * std::sin(a)};
}

// Where the segment a-b crosses the 0-degree ray (x > 0, y = 0), as a distance from the pole.
double crossingRadius(const reconstruction::PolarPoint& a, const reconstruction::PolarPoint& b) {
    const QPointF p = cartesian(a), q = cartesian(b);
    const double dy = q.y() - p.y();
    if (dy == 0.0) return (p.x() + q.x()) / 2.0;
    const double t = -p.y() / dy;
    return p.x() + t * (q.x() - p.x());
}

void appendStep(QList<QPointF>& out, const reconstruction::PolarPoint& a,
                const reconstruction::PolarPoint& b) {
    if (std::abs(b.angle_deg - a.angle_deg) > 180.0) {
        const double r = crossingRadius(a, b);
        // A step through the pole itself: the chart's way round the pole is the step.
        if (!(r > 0.0)) {
            out.append({b.angle_deg, b.radius_mm});
            return;
        }
        // Leaving over 360 and coming back under 0 (clockwise), or the other way round.
        const bool clockwise = a.angle_deg > b.angle_deg;
        out.append({clockwise ? 360.0 + kOffRange_deg : -kOffRange_deg, r});
        out.append({clockwise ? -kOffRange_deg : 360.0 + kOffRange_deg, r});
    }
    out.append({b.angle_deg, b.radius_mm});
}

}  // namespace

QList<QPointF> polarPolyline(const std::vector<reconstruction::PolarPoint>& points, bool closed) {
    QList<QPointF> out;
    if (points.empty()) return out;
    out.append({points.front().angle_deg, points.front().radius_mm});
    for (std::size_t i = 1; i < points.size(); ++i) appendStep(out, points[i - 1], points[i]);
    if (closed && points.size() > 2) appendStep(out, points.back(), points.front());
    return out;
}

}  // namespace caliper3d::app

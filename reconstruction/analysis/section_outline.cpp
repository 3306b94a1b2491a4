#include "reconstruction/analysis/section_outline.h"

#include <cmath>
#include <vector>

#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include "reconstruction/section/arm_geometry.h"
#include "reconstruction/section/ellipse_fit.h"
#include "reconstruction/section/section_analysis.h"

namespace caliper3d::reconstruction {

namespace {

PolarPoint polar(double x, double y) {
    return {wrap360(glm::degrees(std::atan2(y, x))), std::hypot(x, y)};
}

// The ellipse in the plane of arm 1 (u) and the frame's side (v), as the analyser fits it.
OutlineEllipse fitOutlineEllipse(const WellGeometry& g, const std::vector<double>& knots,
                                 double arm1Angle_deg) {
    OutlineEllipse out;
    const int m = g.options().splinePoints;
    std::vector<double> r(static_cast<std::size_t>(m));
    if (g.table().armCount == 2) {
        // The two-pad circle: its own figures, as the report takes them (knot 0 is pad 1,
        // the opposite knot pad 2).
        const double r1 = knots.front(), r2 = knots[knots.size() / 2];
        out.major_mm = out.minor_mm = r1 + r2;
        out.centre = polar((r1 - r2) / 2.0, 0.0);
        out.centre.angle_deg = wrap360(out.centre.angle_deg + arm1Angle_deg);
        out.majorAngle_deg = std::fmod(arm1Angle_deg, 180.0);
        return out;
    }
    const SectionShape shape = SectionAnalyzer(g.knotCount(), m).analyse(knots.data(), r.data());
    double cu = shape.centroidU_mm, cv = shape.centroidV_mm;
    if (shape.ellipseFitted) {
        std::vector<double> u(r.size()), v(r.size());
        for (std::size_t j = 0; j < r.size(); ++j) {
            const double phi = glm::two_pi<double>() * static_cast<double>(j) / m;
            u[j] = r[j] * std::cos(phi);
            v[j] = r[j] * std::sin(phi);
        }
        const Ellipse e = fitEllipse(u.data(), v.data(), m);
        cu = e.centreX;
        cv = e.centreY;
    }
    out.fitted = shape.ellipseFitted;
    out.major_mm = shape.dmax_mm;
    out.minor_mm = shape.dmin_mm;
    out.centre = polar(cu, cv);
    out.centre.angle_deg = wrap360(out.centre.angle_deg + arm1Angle_deg);
    out.majorAngle_deg = std::fmod(wrap360(shape.majorAngle_deg + arm1Angle_deg), 180.0);
    return out;
}

}  // namespace

SectionOutline sectionOutline(const WellGeometry& g, std::size_t row, AngleReference reference,
                              int samples) {
    SectionOutline out;
    out.reference = reference;
    const SectionFrame& frame = g.frame(row);
    out.arm1Angle_deg = arm1Angle_deg(frame, reference);
    out.bitRadius_mm = g.bitRadius_mm(row);
    if (referenceKnown(g, row, AngleReference::North))
        out.northAngle_deg = angleFromReference_deg(
            frame, referenceDirection(frame.tangent, AngleReference::North), reference);
    const Ned& t = frame.tangent;
    // Within 0.06 degrees of vertical the high side is rounding noise (as for an azimuth).
    if (std::hypot(t.x, t.y) >= 1e-3 && referenceKnown(g, row, AngleReference::HighSide))
        out.highSideAngle_deg = angleFromReference_deg(
            frame, referenceDirection(t, AngleReference::HighSide), reference);
    out.measured = g.measured(row);
    if (!out.measured) return out;

    const int arms = g.table().armCount;
    std::vector<double> pads(static_cast<std::size_t>(arms));
    g.repairRadii(row, pads.data());
    for (int k = 0; k < arms; ++k)
        out.pads.push_back({wrap360(out.arm1Angle_deg + armClockwiseAngle_deg(k + 1, arms)),
                            pads[static_cast<std::size_t>(k)]});

    std::vector<double> knots(static_cast<std::size_t>(g.knotCount()));
    g.sectionKnots(row, knots.data());
    const int n = samples > 0 ? samples : g.options().splinePoints;
    std::vector<double> r(static_cast<std::size_t>(n));
    PeriodicSplineSampler(g.knotCount(), n).sample(knots.data(), r.data());
    for (int j = 0; j < n; ++j)
        out.spline.push_back(
            {wrap360(out.arm1Angle_deg + 360.0 * j / n), r[static_cast<std::size_t>(j)]});

    out.ellipse = fitOutlineEllipse(g, knots, out.arm1Angle_deg);
    return out;
}

std::vector<PolarPoint> ellipsePoints(const OutlineEllipse& e, int n) {
    const double c = glm::radians(e.centre.angle_deg), a = glm::radians(e.majorAngle_deg);
    const double cx = e.centre.radius_mm * std::cos(c), cy = e.centre.radius_mm * std::sin(c);
    std::vector<PolarPoint> out;
    for (int j = 0; j < n; ++j) {
        const double s = glm::two_pi<double>() * j / n;
        const double x = e.major_mm / 2.0 * std::cos(s), y = e.minor_mm / 2.0 * std::sin(s);
        out.push_back(
            polar(cx + x * std::cos(a) - y * std::sin(a), cy + x * std::sin(a) + y * std::cos(a)));
    }
    return out;
}

std::vector<PolarPoint> ellipseAxis(const OutlineEllipse& e, bool major, int n) {
    const double c = glm::radians(e.centre.angle_deg);
    const double a = glm::radians(e.majorAngle_deg + (major ? 0.0 : 90.0));
    const double half = (major ? e.major_mm : e.minor_mm) / 2.0;
    const double cx = e.centre.radius_mm * std::cos(c), cy = e.centre.radius_mm * std::sin(c);
    std::vector<PolarPoint> out;
    for (int j = 0; j < n; ++j) {
        const double s = n > 1 ? -half + 2.0 * half * j / (n - 1) : 0.0;
        out.push_back(polar(cx + s * std::cos(a), cy + s * std::sin(a)));
    }
    return out;
}

}  // namespace caliper3d::reconstruction

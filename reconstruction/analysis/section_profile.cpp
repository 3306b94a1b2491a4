#include "reconstruction/analysis/section_profile.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include "reconstruction/analysis/section_angle_reference.h"
#include "reconstruction/section/arm_geometry.h"

namespace caliper3d::reconstruction {

namespace {

double cross(double ax, double ay, double bx, double by) {
    return ax * by - ay * bx;
}

// atan2 within about 1e-5 rad (a minimax polynomial of atan on [-1, 1]). The angles only say
// which rays an edge of the outline answers; each crossing itself is exact, and two edges that
// meet at a vertex use that vertex's one angle, so no ray falls between them.
double roughAtan2(double y, double x) {
    const double ax = std::abs(x), ay = std::abs(y);
    const double big = std::max(ax, ay);
    if (big == 0.0) return 0.0;
    const double z = std::min(ax, ay) / big, z2 = z * z;
    double a =
        z * (0.99997726 +
             z2 * (-0.33262347 +
                   z2 * (0.19354346 + z2 * (-0.11643287 + z2 * (0.05265332 - z2 * 0.01172120)))));
    if (ay > ax) a = glm::half_pi<double>() - a;
    if (x < 0.0) a = glm::pi<double>() - a;
    return y < 0.0 ? -a : a;
}

}  // namespace

SectionProfiler::SectionProfiler(const WellGeometry& geometry, int bins)
    : m_geometry(geometry),
      m_bins(bins),
      m_knots(static_cast<std::size_t>(geometry.knotCount())),
      m_sampled(static_cast<std::size_t>(geometry.sampler().samples())),
      m_x(m_sampled.size()),
      m_y(m_sampled.size()),
      m_angle(m_sampled.size()) {
    const auto m = static_cast<double>(m_sampled.size());
    for (std::size_t j = 0; j < m_sampled.size(); ++j) {
        m_sampleCos.push_back(std::cos(glm::two_pi<double>() * static_cast<double>(j) / m));
        m_sampleSin.push_back(std::sin(glm::two_pi<double>() * static_cast<double>(j) / m));
    }
    for (int b = 0; b < bins; ++b) {
        m_cos.push_back(std::cos(glm::two_pi<double>() * b / bins));
        m_sin.push_back(std::sin(glm::two_pi<double>() * b / bins));
    }
}

bool SectionProfiler::profile(std::size_t row, double* radius_mm) {
    const WellGeometry& g = m_geometry;
    if (!g.measured(row) || !referenceKnown(g, row, AngleReference::North)) return false;
    const double arm1 = arm1Angle_deg(g.frame(row), AngleReference::North);
    if (!std::isfinite(arm1)) return false;
    g.sectionKnots(row, m_knots.data());
    g.sampler().sample(m_knots.data(), m_sampled.data());

    // The sampled wall in the plane: x towards north, y 90 degrees clockwise from it; the
    // centroid of the polygon's area (shoelace), then every point about it.
    const std::size_t m = m_sampled.size();
    const double c1 = std::cos(glm::radians(arm1)), s1 = std::sin(glm::radians(arm1));
    double area2 = 0.0, cx = 0.0, cy = 0.0;
    for (std::size_t j = 0; j < m; ++j) {
        // Sample j lies 360 j / m degrees clockwise from arm 1, arm 1 at `arm1` from north.
        const double c = c1 * m_sampleCos[j] - s1 * m_sampleSin[j];
        const double s = s1 * m_sampleCos[j] + c1 * m_sampleSin[j];
        m_x[j] = m_sampled[j] * c;
        m_y[j] = m_sampled[j] * s;
    }
    for (std::size_t j = 0; j < m; ++j) {
        const std::size_t k = (j + 1) % m;
        const double c = cross(m_x[j], m_y[j], m_x[k], m_y[k]);
        area2 += c;
        cx += (m_x[j] + m_x[k]) * c;
        cy += (m_y[j] + m_y[k]) * c;
    }
    if (!(std::abs(area2) > 0.0)) return false;
    cx /= 3.0 * area2;
    cy /= 3.0 * area2;
    for (std::size_t j = 0; j < m; ++j) {
        m_x[j] -= cx;
        m_y[j] -= cy;
        m_angle[j] = roughAtan2(m_y[j], m_x[j]);
    }

    // Each edge of the polygon answers the bins whose rays cross it; where a ray crosses the
    // wall more than once (an outline not star-shaped about its centre) the farthest crossing.
    const double step = glm::two_pi<double>() / m_bins;
    std::fill(radius_mm, radius_mm + m_bins, -1.0);
    for (std::size_t j = 0; j < m; ++j) {
        const std::size_t k = (j + 1) % m;
        const double t0 = m_angle[j];
        double dt = m_angle[k] - t0;
        if (dt > glm::pi<double>()) dt -= glm::two_pi<double>();
        if (dt < -glm::pi<double>()) dt += glm::two_pi<double>();
        const double lo = std::min(t0, t0 + dt), hi = std::max(t0, t0 + dt);
        const double ex = m_x[k] - m_x[j], ey = m_y[k] - m_y[j];
        for (auto b = static_cast<long>(std::ceil(lo / step)); static_cast<double>(b) * step <= hi;
             ++b) {
            long bin = b;  // lo and hi lie within (-2 pi, 2 pi)
            if (bin < 0) bin += m_bins;
            if (bin >= m_bins) bin -= m_bins;
            const double ux = m_cos[static_cast<std::size_t>(bin)];
            const double uy = m_sin[static_cast<std::size_t>(bin)];
            const double denominator = cross(ux, uy, ex, ey);
            if (std::abs(denominator) < 1e-12) continue;
            const double s = cross(m_x[j], m_y[j], ex, ey) / denominator;
            double& out = radius_mm[bin];
            out = std::max(out, s);
        }
    }
    for (int b = 0; b < m_bins; ++b)
        if (!(radius_mm[b] > 0.0)) return false;
    return true;
}

double profileAngleAzimuth_deg(const SectionFrame& frame, double angle_deg) {
    const Ned r = referenceDirection(frame.tangent, AngleReference::North);
    const Ned right = glm::cross(frame.tangent, r);
    const double a = glm::radians(angle_deg);
    const Ned d = std::cos(a) * r + std::sin(a) * right;
    if (std::hypot(d.x, d.y) < 1e-3) return std::nan("");
    return wrap360(glm::degrees(std::atan2(d.y, d.x)));
}

}  // namespace caliper3d::reconstruction

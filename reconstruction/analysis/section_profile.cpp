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

}  // namespace

SectionProfiler::SectionProfiler(const WellGeometry& geometry, int bins)
    : m_geometry(geometry),
      m_bins(bins),
      m_knots(static_cast<std::size_t>(geometry.knotCount())),
      m_sampled(static_cast<std::size_t>(geometry.sampler().samples())),
      m_x(m_sampled.size()),
      m_y(m_sampled.size()),
      m_angle(m_sampled.size()) {
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
    const double a1 = glm::radians(arm1);
    double area2 = 0.0, cx = 0.0, cy = 0.0;
    for (std::size_t j = 0; j < m; ++j) {
        const double phi = a1 + glm::two_pi<double>() * static_cast<double>(j) / m;
        m_x[j] = m_sampled[j] * std::cos(phi);
        m_y[j] = m_sampled[j] * std::sin(phi);
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
        m_angle[j] = std::atan2(m_y[j], m_x[j]);
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
            const long bin = ((b % m_bins) + m_bins) % m_bins;
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

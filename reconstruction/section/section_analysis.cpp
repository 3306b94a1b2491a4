#include "reconstruction/section/section_analysis.h"

#include <cmath>

#include <boost/math/constants/constants.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "reconstruction/section/arm_geometry.h"
#include "reconstruction/section/ellipse_fit.h"

namespace caliper3d::reconstruction {

namespace {
constexpr double kTwoPi = boost::math::constants::two_pi<double>();
}

SectionAnalyzer::SectionAnalyzer(int knots, int samples) : m_sampler(knots, samples) {
    m_cos.resize(static_cast<std::size_t>(samples));
    m_sin.resize(static_cast<std::size_t>(samples));
    for (int j = 0; j < samples; ++j) {
        const double phi = kTwoPi * j / samples;
        m_cos[static_cast<std::size_t>(j)] = std::cos(phi);
        m_sin[static_cast<std::size_t>(j)] = std::sin(phi);
    }
}

SectionShape SectionAnalyzer::analyse(const double* padRadii_mm, double* r) const {
    const int m = m_sampler.samples();
    m_sampler.sample(padRadii_mm, r);
    // Points at equal angles from the tool axis: the shoelace cross product of
    // neighbours is r_j r_j+1 sin(2 pi / M).
    constexpr int kMaxStack = 256;
    double uBuf[kMaxStack], vBuf[kMaxStack];
    std::vector<double> uHeap, vHeap;
    double* u = uBuf;
    double* v = vBuf;
    if (m > kMaxStack) {
        uHeap.resize(static_cast<std::size_t>(m));
        vHeap.resize(static_cast<std::size_t>(m));
        u = uHeap.data();
        v = vHeap.data();
    }
    for (int j = 0; j < m; ++j) {
        u[j] = r[j] * m_cos[static_cast<std::size_t>(j)];
        v[j] = r[j] * m_sin[static_cast<std::size_t>(j)];
    }
    double twiceArea = 0.0, cu = 0.0, cv = 0.0;
    double suu = 0.0, svv = 0.0, suv = 0.0;
    for (int j = 0; j < m; ++j) {
        const int k = j + 1 == m ? 0 : j + 1;
        const double cross = u[j] * v[k] - u[k] * v[j];
        twiceArea += cross;
        cu += (u[j] + u[k]) * cross;
        cv += (v[j] + v[k]) * cross;
        // Second moments of the polygon about the tool axis (Steger 1996).
        suu += (u[j] * u[j] + u[j] * u[k] + u[k] * u[k]) * cross;
        svv += (v[j] * v[j] + v[j] * v[k] + v[k] * v[k]) * cross;
        suv += (u[j] * v[k] + 2.0 * u[j] * v[j] + 2.0 * u[k] * v[k] + u[k] * v[j]) * cross;
    }
    SectionShape s;
    const double area = twiceArea / 2.0;
    s.area_mm2 = std::abs(area);
    s.equivalentDiameter_mm = 2.0 * std::sqrt(s.area_mm2 / boost::math::constants::pi<double>());
    if (area != 0.0) {
        s.centroidU_mm = cu / (6.0 * area);
        s.centroidV_mm = cv / (6.0 * area);
    }
    s.centreOffset_mm = std::hypot(s.centroidU_mm, s.centroidV_mm);

    const Ellipse e = fitEllipse(u, v, m);
    if (e.valid) {
        s.dmax_mm = e.major;
        s.dmin_mm = e.minor;
        s.majorAngle_deg = glm::degrees(e.majorAngle_rad);
        s.ellipseFitted = true;
    } else if (area != 0.0) {
        // The ellipse of the same second moments: semi-axes 2 sqrt(eigenvalue).
        const double iuu = suu / (12.0 * area) - s.centroidU_mm * s.centroidU_mm;
        const double ivv = svv / (12.0 * area) - s.centroidV_mm * s.centroidV_mm;
        const double iuv = suv / (24.0 * area) - s.centroidU_mm * s.centroidV_mm;
        const double mean = (iuu + ivv) / 2.0, diff = std::hypot((iuu - ivv) / 2.0, iuv);
        s.dmax_mm = 4.0 * std::sqrt(std::max(mean + diff, 0.0));
        s.dmin_mm = 4.0 * std::sqrt(std::max(mean - diff, 0.0));
        double angle = glm::degrees(0.5 * std::atan2(2.0 * iuv, iuu - ivv));
        s.majorAngle_deg = angle < 0.0 ? angle + 180.0 : angle;
    }
    if (s.majorAngle_deg >= 180.0) s.majorAngle_deg -= 180.0;
    s.ellipticity = s.dmin_mm > 0.0 ? s.dmax_mm / s.dmin_mm : 0.0;
    return s;
}

double inPlaneAzimuth_deg(const SectionFrame& frame, double clockwise_deg) {
    const Ned d = frame.direction(glm::radians(clockwise_deg));
    if (std::hypot(d.x, d.y) < 1e-3) return std::nan("");
    return wrap360(glm::degrees(std::atan2(d.y, d.x)));
}

double angleFromHighSide_deg(const SectionFrame& frame, double inc_deg, double azi_deg,
                             double clockwise_deg) {
    const Ned d = frame.direction(glm::radians(clockwise_deg));
    const Ned hs = highSide(inc_deg, azi_deg);
    const Ned right = glm::cross(frame.tangent, hs);
    return wrap360(glm::degrees(std::atan2(glm::dot(d, right), glm::dot(d, hs))));
}

}  // namespace caliper3d::reconstruction

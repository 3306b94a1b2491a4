#include "reconstruction/path/course_dogleg.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

namespace caliper3d::reconstruction {

namespace {

glm::dvec3 tangent(const PathPoint& p) {
    const double inc = glm::radians(p.inc_deg), azi = glm::radians(p.azi_deg);
    return {std::sin(inc) * std::cos(azi), std::sin(inc) * std::sin(azi), std::cos(inc)};
}

// The mean hole direction (and depth) of the points with md in a window that only moves down
// the hole: each point is added to running sums as the window's bottom passes it and taken away
// as its top does, so a mean costs what the points entering and leaving cost. (Prefix sums of
// the tangents and depths did the same with two arrays as long as the path written and read
// again: on a log of a million rows that memory took more time than the rest of the loop.)
class SlidingMean {
public:
    // `tangents`: each point's unit tangent, or null to take it from the point's angles.
    SlidingMean(const std::vector<PathPoint>& path, const glm::dvec3* tangents)
        : m_path(path), m_tangents(tangents) {}

    struct Mean {
        glm::dvec3 direction;
        double md;
    };

    // Mean tangent (and depth) of the points with md in [from, to]; the nearest point's when
    // none is. `from` and `to` never decrease from one call to the next.
    Mean operator()(double from, double to) {
        const std::size_t n = m_path.size();
        // In first, then out: a point below `from` is at most `to`, so it was added.
        for (; m_hi < n && !(to < m_path[m_hi].md); ++m_hi) {
            m_sum += tangentOf(m_hi);
            m_mdSum += m_path[m_hi].md;
        }
        for (; m_lo < m_hi && m_path[m_lo].md < from; ++m_lo) {
            m_sum -= tangentOf(m_lo);
            m_mdSum -= m_path[m_lo].md;
        }
        if (m_lo == m_hi) {  // empty: the sums start again from nothing, with no rounding left
            m_sum = glm::dvec3(0.0);
            m_mdSum = 0.0;
        } else {
            const double length = glm::length(m_sum);
            if (length > 0.0) return {m_sum / length, m_mdSum / static_cast<double>(m_hi - m_lo)};
        }
        const PathPoint& near = m_path[m_lo == n ? m_lo - 1 : m_lo];
        return {tangent(near), near.md};
    }

private:
    glm::dvec3 tangentOf(std::size_t i) const {
        return m_tangents ? m_tangents[i] : tangent(m_path[i]);
    }

    const std::vector<PathPoint>& m_path;
    const glm::dvec3* m_tangents;
    std::size_t m_lo = 0, m_hi = 0;  // the points in the window: [m_lo, m_hi)
    glm::dvec3 m_sum{0.0};
    double m_mdSum = 0.0;
};

// The angle between unit vectors a and b, radians. |a - b| is 2 sin(angle / 2); most courses of
// a log turn by less than 5.7 degrees, where the angle is taken from that chord by the series of
// arcsine to x^11 (the next term is under 5e-18 of x below x = 0.05): std::atan2 of the cross
// and dot products, taken for every row, was a ninth of placing a field's well (`perf` of
// reconstruction_bench's placeFieldWell).
double angleBetweenUnit(const glm::dvec3& a, const glm::dvec3& b) {
    const double x = glm::length(a - b) / 2.0;
    if (x < 0.05) {
        const double x2 = x * x;
        const double tail =
            1.0 / 6.0 +
            x2 * (3.0 / 40.0 + x2 * (5.0 / 112.0 + x2 * (35.0 / 1152.0 + x2 * (63.0 / 2816.0))));
        return 2.0 * (x + x * x2 * tail);
    }
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

}  // namespace

namespace {

void setDls(std::vector<PathPoint>& path, const glm::dvec3* tangents, double course_m,
            double window_m) {
    if (path.size() < 2 || !(path.back().md - path.front().md >= 1.0)) return;
    SlidingMean upper(path, tangents), lower(path, tangents);
    const double top = path.front().md, bottom = path.back().md;
    for (PathPoint& p : path) {
        const double a = std::max(top, p.md - course_m / 2.0);
        const double b = std::min(bottom, p.md + course_m / 2.0);
        // Each end's direction belongs to the mean depth of the points averaged there.
        const SlidingMean::Mean ta = upper(a - window_m, a + window_m);
        const SlidingMean::Mean tb = lower(b - window_m, b + window_m);
        const double dogleg = glm::degrees(angleBetweenUnit(ta.direction, tb.direction));
        const double course = tb.md - ta.md;
        p.dls_degPer30m = course > 0.0 ? dogleg * 30.0 / course : 0.0;
    }
}

}  // namespace

void setCourseLengthDls(std::vector<PathPoint>& path, double course_m, double window_m) {
    setDls(path, nullptr, course_m, window_m);
}

void setCourseLengthDls(std::vector<PathPoint>& path, const std::vector<glm::dvec3>& tangents,
                        double course_m, double window_m) {
    if (tangents.size() != path.size())
        throw std::invalid_argument("setCourseLengthDls: a tangent per path point");
    setDls(path, tangents.data(), course_m, window_m);
}

}  // namespace caliper3d::reconstruction

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

// Prefix sums of the unit tangents and of the depths: the mean direction over an interval of
// md, and the mean depth it belongs to.
class MeanDirection {
public:
    // `tangents`: each point's unit tangent, or null to take it from the point's angles.
    MeanDirection(const std::vector<PathPoint>& path, const glm::dvec3* tangents) : m_path(path) {
        m_sum.reserve(path.size() + 1);
        m_sum.emplace_back(0.0);
        m_mdSum.reserve(path.size() + 1);
        m_mdSum.push_back(0.0);
        for (std::size_t i = 0; i < path.size(); ++i) {
            m_sum.push_back(m_sum.back() + (tangents ? tangents[i] : tangent(path[i])));
            m_mdSum.push_back(m_mdSum.back() + path[i].md);
        }
    }

    struct Mean {
        glm::dvec3 direction;
        double md;
    };

    // The points with md in [from, to] as rows [lo, hi): what std::lower_bound(from) and
    // std::upper_bound(to) give, found by stepping forward from the last call's rows, since the
    // course's ends only move down the hole (two binary searches a point cost more than the
    // rest of the loop on a log of a million rows).
    struct Window {
        std::size_t lo = 0, hi = 0;
    };

    // Mean tangent (and depth) of the points with md in [from, to]; the nearest point's when
    // none is. `from` and `to` never decrease from one call with `window` to the next.
    Mean operator()(Window& window, double from, double to) const {
        const std::size_t n = m_path.size();
        while (window.lo < n && m_path[window.lo].md < from) ++window.lo;
        while (window.hi < n && !(to < m_path[window.hi].md)) ++window.hi;
        const std::size_t a = window.lo, b = window.hi;
        if (a < b) {
            const glm::dvec3 s = m_sum[b] - m_sum[a];
            const double length = glm::length(s);
            if (length > 0.0)
                return {s / length, (m_mdSum[b] - m_mdSum[a]) / static_cast<double>(b - a)};
        }
        const PathPoint& near = m_path[a == n ? a - 1 : a];
        return {tangent(near), near.md};
    }

private:
    const std::vector<PathPoint>& m_path;
    std::vector<glm::dvec3> m_sum;
    std::vector<double> m_mdSum;
};

}  // namespace

namespace {

void setDls(std::vector<PathPoint>& path, const glm::dvec3* tangents, double course_m,
            double window_m) {
    if (path.size() < 2 || !(path.back().md - path.front().md >= 1.0)) return;
    const MeanDirection mean(path, tangents);
    const double top = path.front().md, bottom = path.back().md;
    MeanDirection::Window upper, lower;
    for (PathPoint& p : path) {
        const double a = std::max(top, p.md - course_m / 2.0);
        const double b = std::min(bottom, p.md + course_m / 2.0);
        // Each end's direction belongs to the mean depth of the points averaged there.
        const MeanDirection::Mean ta = mean(upper, a - window_m, a + window_m);
        const MeanDirection::Mean tb = mean(lower, b - window_m, b + window_m);
        const double dogleg =
            glm::degrees(std::atan2(glm::length(glm::cross(ta.direction, tb.direction)),
                                    glm::dot(ta.direction, tb.direction)));
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

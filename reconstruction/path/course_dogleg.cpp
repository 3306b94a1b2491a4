#include "reconstruction/path/course_dogleg.h"

#include <algorithm>
#include <cmath>

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
    explicit MeanDirection(const std::vector<PathPoint>& path) : m_path(path) {
        m_sum.reserve(path.size() + 1);
        m_sum.emplace_back(0.0);
        m_mdSum.reserve(path.size() + 1);
        m_mdSum.push_back(0.0);
        for (const PathPoint& p : path) {
            m_sum.push_back(m_sum.back() + tangent(p));
            m_mdSum.push_back(m_mdSum.back() + p.md);
        }
    }

    struct Mean {
        glm::dvec3 direction;
        double md;
    };

    // Mean tangent (and depth) of the points with md in [from, to]; the nearest point's when
    // none is.
    Mean operator()(double from, double to) const {
        auto byMd = [](const PathPoint& p, double md) { return p.md < md; };
        const auto lo = std::lower_bound(m_path.begin(), m_path.end(), from, byMd);
        const auto hi = std::upper_bound(m_path.begin(), m_path.end(), to,
                                         [](double md, const PathPoint& p) { return md < p.md; });
        if (lo < hi) {
            const auto a = static_cast<std::size_t>(lo - m_path.begin());
            const auto b = static_cast<std::size_t>(hi - m_path.begin());
            const glm::dvec3 s = m_sum[b] - m_sum[a];
            const double length = glm::length(s);
            if (length > 0.0)
                return {s / length, (m_mdSum[b] - m_mdSum[a]) / static_cast<double>(b - a)};
        }
        const auto near = lo == m_path.end() ? lo - 1 : lo;
        return {tangent(*near), near->md};
    }

private:
    const std::vector<PathPoint>& m_path;
    std::vector<glm::dvec3> m_sum;
    std::vector<double> m_mdSum;
};

}  // namespace

void setCourseLengthDls(std::vector<PathPoint>& path, double course_m, double window_m) {
    if (path.size() < 2 || !(path.back().md - path.front().md >= 1.0)) return;
    const MeanDirection mean(path);
    const double top = path.front().md, bottom = path.back().md;
    for (PathPoint& p : path) {
        const double a = std::max(top, p.md - course_m / 2.0);
        const double b = std::min(bottom, p.md + course_m / 2.0);
        // Each end's direction belongs to the mean depth of the points averaged there.
        const MeanDirection::Mean ta = mean(a - window_m, a + window_m);
        const MeanDirection::Mean tb = mean(b - window_m, b + window_m);
        const double dogleg =
            glm::degrees(std::atan2(glm::length(glm::cross(ta.direction, tb.direction)),
                                    glm::dot(ta.direction, tb.direction)));
        const double course = tb.md - ta.md;
        p.dls_degPer30m = course > 0.0 ? dogleg * 30.0 / course : 0.0;
    }
}

}  // namespace caliper3d::reconstruction

#include "reconstruction/path/survey_interpolation.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "reconstruction/section/arm_geometry.h"
#include "reconstruction/section/section_frame.h"

namespace caliper3d::reconstruction {

std::vector<SurveyStation> surveyStations(const io::SurveyTable& survey) {
    std::vector<SurveyStation> out(survey.stationCount());
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = {survey.md_m[i], survey.inc_deg[i], survey.azi_deg[i]};
    return out;
}

SurveyStation surfaceTieIn(const SurveyStation& first) {
    return {0.0, 0.0, first.azi_deg};
}

std::vector<SurveyStation> tiedToSurface(std::vector<SurveyStation> stations) {
    if (!stations.empty() && stations.front().md > 0.0)
        stations.insert(stations.begin(), surfaceTieIn(stations.front()));
    return stations;
}

namespace {
SurveyStation fromTangent(double md, const Ned& t, double fallbackAzi_deg) {
    const double horizontal = std::hypot(t.x, t.y);
    const double inc = glm::degrees(std::atan2(horizontal, t.z));
    // A vertical tangent has no azimuth: keep the course's so that the
    // position formula (which multiplies it by sin inc = 0) is unaffected.
    const double azi =
        horizontal < 1e-12 ? fallbackAzi_deg : wrap360(glm::degrees(std::atan2(t.y, t.x)));
    return {md, inc, azi};
}
}  // namespace

SurveyStation stationOnArc(const SurveyStation& a, const SurveyStation& b, double md) {
    const double course = b.md - a.md;
    if (!(course > 0.0)) return a;
    const double f = std::clamp((md - a.md) / course, 0.0, 1.0);
    const Ned t1 = holeTangent(a.inc_deg, a.azi_deg), t2 = holeTangent(b.inc_deg, b.azi_deg);
    const double beta = std::acos(std::clamp(glm::dot(t1, t2), -1.0, 1.0));
    Ned t;
    if (beta < 1e-9) {
        t = glm::normalize((1.0 - f) * t1 + f * t2);
    } else {
        // Spherical linear interpolation of the tangent: the minimum-curvature
        // arc turns its tangent uniformly with measured depth (Taylor & Mason 1972).
        t = (std::sin((1.0 - f) * beta) * t1 + std::sin(f * beta) * t2) / std::sin(beta);
    }
    return fromTangent(md, t, f < 0.5 ? a.azi_deg : b.azi_deg);
}

std::vector<PathPoint> interpolateSurveyPath(const std::vector<SurveyStation>& survey,
                                             const std::vector<double>& md) {
    if (survey.size() < 2)
        throw std::invalid_argument("survey interpolation needs at least two stations");
    const std::vector<PathPoint> stations = minimumCurvaturePath(survey);
    std::vector<PathPoint> out(md.size());
    std::size_t course = 0;  // index of the station that starts the current course
    for (std::size_t i = 0; i < md.size(); ++i) {
        const double d = md[i];
        if (i > 0 && d < md[i - 1]) course = 0;  // not ascending: search again from the top
        while (course + 2 < survey.size() && d > survey[course + 1].md) ++course;
        const SurveyStation& a = survey[course];
        const SurveyStation& b = survey[course + 1];
        const PathPoint& start = stations[course];
        PathPoint p;
        p.md = d;
        if (d <= a.md || d >= b.md) {
            // Outside the survey, or exactly on a station: straight along the end tangent.
            const bool below = d >= b.md;
            const SurveyStation& s = below ? b : a;
            const PathPoint& base = below ? stations[course + 1] : start;
            const Ned t = holeTangent(s.inc_deg, s.azi_deg);
            const double ds = d - s.md;
            p.north = base.north + ds * t.x;
            p.east = base.east + ds * t.y;
            p.tvd = base.tvd + ds * t.z;
            p.inc_deg = s.inc_deg;
            p.azi_deg = s.azi_deg;
            p.dls_degPer30m = (d == b.md || d == a.md)
                                  ? stations[below ? course + 1 : course].dls_degPer30m
                                  : 0.0;
        } else {
            const SurveyStation here = stationOnArc(a, b, d);
            const MinimumCurvatureStep step = minimumCurvatureStep(a, here);
            p.north = start.north + step.dNorth;
            p.east = start.east + step.dEast;
            p.tvd = start.tvd + step.dTvd;
            p.inc_deg = here.inc_deg;
            p.azi_deg = here.azi_deg;
            p.dls_degPer30m = stations[course + 1].dls_degPer30m;
        }
        if (i > 0) {
            const PathPoint& q = out[i - 1];
            const double c =
                glm::dot(holeTangent(q.inc_deg, q.azi_deg), holeTangent(p.inc_deg, p.azi_deg));
            p.dogleg_deg = glm::degrees(std::acos(std::clamp(c, -1.0, 1.0)));
        }
        out[i] = p;
    }
    return out;
}

SurveyPositionCheck checkSurveyPositions(const io::SurveyTable& survey) {
    SurveyPositionCheck check;
    const std::vector<PathPoint> path = minimumCurvaturePath(surveyStations(survey));
    auto have = [](const std::vector<double>& v, std::size_t i) {
        return i < v.size() && std::isfinite(v[i]);
    };
    std::size_t tvd0 = path.size(), ne0 = path.size();
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (have(survey.tvd_m, i)) {
            if (tvd0 == path.size()) tvd0 = i;
            const double d =
                std::abs((survey.tvd_m[i] - survey.tvd_m[tvd0]) - (path[i].tvd - path[tvd0].tvd));
            ++check.tvdStations;
            if (d > check.maxTvdDifference_m) {
                check.maxTvdDifference_m = d;
                check.maxTvdAt_m = path[i].md;
            }
        }
        if (have(survey.north_m, i) && have(survey.east_m, i)) {
            if (ne0 == path.size()) ne0 = i;
            const double d = std::hypot(
                (survey.north_m[i] - survey.north_m[ne0]) - (path[i].north - path[ne0].north),
                (survey.east_m[i] - survey.east_m[ne0]) - (path[i].east - path[ne0].east));
            ++check.horizontalStations;
            if (d > check.maxHorizontalDifference_m) {
                check.maxHorizontalDifference_m = d;
                check.maxHorizontalAt_m = path[i].md;
            }
        }
    }
    if (check.horizontalStations > 1) {
        // Least-squares similarity (turn and scale) of the computed displacements
        // onto the file's, as complex numbers east + i north: file ~ k * computed.
        using Complex = std::complex<double>;
        Complex num(0.0, 0.0);
        double den = 0.0;
        auto displacements = [&](std::size_t i) {
            return std::pair<Complex, Complex>{
                {path[i].east - path[ne0].east, path[i].north - path[ne0].north},
                {survey.east_m[i] - survey.east_m[ne0], survey.north_m[i] - survey.north_m[ne0]}};
        };
        for (std::size_t i = ne0; i < path.size(); ++i) {
            if (!have(survey.north_m, i) || !have(survey.east_m, i)) continue;
            const auto [ours, theirs] = displacements(i);
            num += std::conj(ours) * theirs;
            den += std::norm(ours);
        }
        if (den > 0.0) {
            const Complex k = num / den;
            check.rotation_deg =
                -glm::degrees(std::arg(k));  // counter-clockwise in (east, north) = anticlockwise
            check.scale = std::abs(k);
            for (std::size_t i = ne0; i < path.size(); ++i) {
                if (!have(survey.north_m, i) || !have(survey.east_m, i)) continue;
                const auto [ours, theirs] = displacements(i);
                check.maxHorizontalAfterFit_m =
                    std::max(check.maxHorizontalAfterFit_m, std::abs(k * ours - theirs));
            }
        }
    }
    return check;
}

std::string describeSurveyPositionCheck(const SurveyPositionCheck& c) {
    char buf[256];
    std::string out;
    if (c.tvdStations > 0) {
        std::snprintf(
            buf, sizeof buf,
            "TVD within %.3f m of minimum curvature over %zu stations (largest at MD %.2f m)",
            c.maxTvdDifference_m, c.tvdStations, c.maxTvdAt_m);
        out += buf;
    }
    if (c.horizontalStations > 0) {
        std::snprintf(buf, sizeof buf,
                      "%snorth/east within %.3f m over %zu stations (largest at MD %.2f m)",
                      out.empty() ? "" : "; ", c.maxHorizontalDifference_m, c.horizontalStations,
                      c.maxHorizontalAt_m);
        out += buf;
        if (c.maxHorizontalDifference_m > kSurveyPositionTolerance_m &&
            c.maxHorizontalAfterFit_m <= kSurveyPositionTolerance_m) {
            std::snprintf(
                buf, sizeof buf,
                ", within %.3f m once turned %.4f deg clockwise and scaled by %.6f (grid north "
                "and grid scale?)",
                c.maxHorizontalAfterFit_m, c.rotation_deg, c.scale);
            out += buf;
        }
    }
    return out;
}

}  // namespace caliper3d::reconstruction

#include "reconstruction/well_path.h"

#include <algorithm>
#include <cmath>

#include "reconstruction/path/survey_interpolation.h"

namespace caliper3d::reconstruction {

namespace {

// The stations the geometry ties its first row to the wellhead with (well_geometry.cpp,
// computeSteps for row 0; interpolateSurveyPath over tiedToSurface for a survey).
std::vector<SurveyStation> tieInStations(const WellGeometry& geometry) {
    if (!geometry.options().survey.empty()) return tiedToSurface(geometry.options().survey);
    const PathPoint& first = geometry.path().front();
    const SurveyStation station{first.md, first.inc_deg, first.azi_deg};
    return {surfaceTieIn(station), station};
}

bool hasUnloggedTop(const WellGeometry& geometry) {
    return geometry.table().rowCount() > 0 && geometry.table().depth_m.front() > 0.0 &&
           !geometry.options().continueFrom;
}

PathSample fromPathPoint(const PathPoint& p, const WellGeometry& geometry) {
    return {p.md, Ned(p.north, p.east, p.tvd) + geometry.options().wellheadOffset, p.inc_deg,
            p.azi_deg};
}

}  // namespace

PathSample pathAt(const WellGeometry& geometry, double md_m) {
    const std::vector<double>& depth = geometry.table().depth_m;
    const double md = std::clamp(md_m, std::min(0.0, depth.front()), depth.back());
    if (md < depth.front()) {
        if (!hasUnloggedTop(geometry)) return fromPathPoint(geometry.path().front(), geometry);
        return fromPathPoint(interpolateSurveyPath(tieInStations(geometry), {md}).front(),
                             geometry);
    }
    const std::size_t row =
        static_cast<std::size_t>(std::lower_bound(depth.begin(), depth.end(), md) - depth.begin());
    const PathPoint& deeper = geometry.path()[row];
    PathSample out{md, geometry.centre(row), deeper.inc_deg, deeper.azi_deg};
    if (row > 0 && depth[row] > md) {
        const double f = (md - depth[row - 1]) / (depth[row] - depth[row - 1]);
        const Ned above = geometry.centre(row - 1);
        out.position = above + (out.position - above) * f;
    }
    return out;
}

std::vector<glm::vec3> unloggedPathLine(const WellGeometry& geometry, double spacing_m) {
    if (!hasUnloggedTop(geometry)) return {};
    const double first = geometry.table().depth_m.front();
    const double step = std::max(spacing_m, first / 10000.0);
    std::vector<double> md;
    for (double d = 0.0; d < first; d += step) md.push_back(d);
    md.push_back(first);
    const std::vector<PathPoint> points = interpolateSurveyPath(tieInStations(geometry), md);
    std::vector<glm::vec3> line;
    line.reserve(points.size());
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
        line.emplace_back(toScene(fromPathPoint(points[i], geometry).position));
    line.emplace_back(toScene(geometry.centre(0)));  // joins the logged path without a gap
    return line;
}

}  // namespace caliper3d::reconstruction

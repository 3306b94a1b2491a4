#include "reconstruction/mesh/wall_point.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "reconstruction/section/periodic_spline.h"
#include "reconstruction/section/section_analysis.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

namespace {

// Signed distance of `p` from row `row`'s section plane along its tangent (positive deeper).
double fromPlane(const WellGeometry& g, std::size_t row, const Ned& p) {
    return glm::dot(p - g.centre(row), g.frame(row).tangent);
}

}  // namespace

WallPoint locateWallPoint(const WellGeometry& g, std::size_t firstRow, std::size_t lastRow,
                          const glm::dvec3& scenePoint) {
    const std::size_t rows = g.path().size();
    WallPoint out;
    if (rows == 0) return out;
    lastRow = std::min(lastRow, rows - 1);
    firstRow = std::min(firstRow, lastRow);
    const Ned p = fromScene(scenePoint);

    // The planes follow one another down the hole, so the signed distance falls as the row
    // grows: the point lies between the last plane it is below and the first it is above.
    std::size_t row = lastRow;
    double s = fromPlane(g, row, p);
    for (std::size_t r = firstRow; r <= lastRow; ++r) {
        const double here = fromPlane(g, r, p);
        if (here > 0.0) continue;
        row = r;
        s = here;
        if (r > firstRow) {
            const double above = fromPlane(g, r - 1, p);
            if (above < -here) {
                row = r - 1;
                s = above;
            }
        }
        break;
    }
    out.row = row;
    out.fromPlane_m = s;

    const SectionFrame& f = g.frame(row);
    const Ned inPlane = p - g.centre(row) - s * f.tangent;
    // Drawn in-plane coordinates from the tool axis, millimetres (u along arm 1, v clockwise).
    double u = glm::dot(inPlane, f.arm1) * 1000.0, v = glm::dot(inPlane, f.side) * 1000.0;
    std::vector<double> knots;
    if (g.measured(row)) {
        knots.resize(static_cast<std::size_t>(g.knotCount()));
        g.sectionKnots(row, knots.data());
    }
    const double exaggeration = g.options().radialExaggeration;
    if (exaggeration != 1.0 && !knots.empty()) {
        // The ring was drawn `exaggeration` times larger about the centroid of its area
        // (lod_levels.cpp, appendRing): shrink the point back about the same centre, the
        // section's as the analysis measures it (shoelace on the sampled spline).
        const SectionAnalyzer analyzer(g.knotCount(), g.options().splinePoints);
        std::vector<double> sampled(static_cast<std::size_t>(analyzer.samples()));
        const SectionShape shape = analyzer.analyse(knots.data(), sampled.data());
        u = shape.centroidU_mm + (u - shape.centroidU_mm) / exaggeration;
        v = shape.centroidV_mm + (v - shape.centroidV_mm) / exaggeration;
    }
    double phi = glm::degrees(std::atan2(v, u));
    if (phi < 0.0) phi += 360.0;
    if (phi >= 360.0) phi -= 360.0;
    out.fromArm1_deg = phi;

    const PathPoint& pp = g.path()[row];
    out.fromHighSide_deg = angleFromHighSide_deg(f, pp.inc_deg, pp.azi_deg, phi);
    out.azimuth_deg = inPlaneAzimuth_deg(f, phi);
    if (g.orientation(row) == WellGeometry::Orientation::Unoriented) {
        // No pad-1 azimuth nor relative bearing: neither north nor the high side is known.
        out.azimuth_deg = out.fromHighSide_deg = std::nan("");
    } else if (!g.holeAzimuthKnown() && pp.inc_deg > 0.0) {
        // As the report: arm 1 placed from RB has no true azimuth; from P1AZ, no high side.
        if (g.orientation(row) == WellGeometry::Orientation::RelativeBearing)
            out.azimuth_deg = std::nan("");
        else
            out.fromHighSide_deg = std::nan("");
    }

    if (!knots.empty()) {
        // The knots sit at equal angles clockwise from arm 1 (WellGeometry::sectionKnots),
        // the spline's parameter counting knots.
        const PeriodicSpline spline(knots);
        out.radius_mm = spline(phi / 360.0 * static_cast<double>(knots.size()));
    }
    return out;
}

}  // namespace caliper3d::reconstruction

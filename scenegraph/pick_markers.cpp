#include "scenegraph/pick_markers.h"

#include <algorithm>
#include <cmath>

#include <Inventor/nodes/SoBaseColor.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoSeparator.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "reconstruction/analysis/pick_comparison.h"
#include "reconstruction/analysis/section_angle_reference.h"
#include "scenegraph/main_thread.h"

namespace caliper3d::scenegraph {

namespace {

// Rows [first, last] of the log within [top, bottom] metres; the nearest row for a point.
std::pair<std::size_t, std::size_t> rowsOf(const io::SectionTable& t, double top, double bottom) {
    const auto begin = t.depth_m.begin(), end = t.depth_m.end();
    std::size_t first = static_cast<std::size_t>(std::lower_bound(begin, end, top) - begin);
    std::size_t last = static_cast<std::size_t>(std::upper_bound(begin, end, bottom) - begin);
    first = std::min(first, t.depth_m.size() - 1);
    last = last == 0 ? 0 : last - 1;
    if (last < first) last = first;
    return {first, last};
}

// The widest arm of a row, millimetres (repaired where an arm is missing).
double widestArm_mm(const reconstruction::WellGeometry& g, std::size_t row) {
    std::vector<double> radii(static_cast<std::size_t>(g.table().armCount));
    g.repairRadii(row, radii.data());
    double widest = 0.0;
    for (double r : radii)
        if (std::isfinite(r)) widest = std::max(widest, r);
    return widest;
}

}  // namespace

reconstruction::Ned wallPointAt(const reconstruction::WellGeometry& g, std::size_t row,
                                double azimuth_deg, double radius_mm) {
    const reconstruction::SectionFrame& frame = g.frame(row);
    const reconstruction::Ned north =
        reconstruction::referenceDirection(frame.tangent, reconstruction::AngleReference::North);
    const reconstruction::Ned right = glm::cross(frame.tangent, north);
    const double a = glm::radians(azimuth_deg);
    const reconstruction::Ned d = std::cos(a) * north + std::sin(a) * right;
    return g.centre(row) + d * (radius_mm / 1000.0);
}

SoSeparator* makePickMarkers(const reconstruction::WellGeometry& g,
                             const std::vector<io::Pick>& picks, double exaggeration) {
    assertMainThread("makePickMarkers");
    auto* root = new SoSeparator;
    root->setName("image_log_picks");
    const io::SectionTable& t = g.table();
    if (t.rowCount() == 0) return root;
    auto* unlit = new SoLightModel;
    unlit->model = SoLightModel::BASE_COLOR;
    auto* style = new SoDrawStyle;
    style->lineWidth = 3.0f;
    auto* colour = new SoBaseColor;
    colour->rgb.setValue(1.0f, 0.0f, 1.0f);
    auto* points = new SoCoordinate3;
    auto* lines = new SoLineSet;
    lines->numVertices.setNum(0);
    int n = 0;
    const double top = t.depth_m.front(), bottom = t.depth_m.back();
    for (const io::Pick& p : picks) {
        if (p.bottom_m < top || p.top_m > bottom || !std::isfinite(p.azimuth_deg)) continue;
        const auto [first, last] = rowsOf(t, p.top_m, p.bottom_m);
        const int sides = reconstruction::isBreakoutPick(p.type) ? 2 : 1;
        for (int side = 0; side < sides; ++side) {
            const double azimuth = p.azimuth_deg + 180.0 * side;
            int vertices = 0;
            auto add = [&](std::size_t row, double outward_mm) {
                const double r = (widestArm_mm(g, row) + outward_mm) * exaggeration;
                const glm::dvec3 s = reconstruction::toScene(wallPointAt(g, row, azimuth, r));
                points->point.set1Value(n++, static_cast<float>(s.x), static_cast<float>(s.y),
                                        static_cast<float>(s.z));
                ++vertices;
            };
            if (first == last) {  // a pick at one depth: a short tick outward from the wall
                add(first, 5.0);
                add(first, 40.0);
            } else {
                for (std::size_t row = first; row <= last; ++row) add(row, 5.0);
            }
            lines->numVertices.set1Value(lines->numVertices.getNum(), vertices);
        }
    }
    root->addChild(unlit);
    root->addChild(style);
    root->addChild(colour);
    root->addChild(points);
    root->addChild(lines);
    return root;
}

}  // namespace caliper3d::scenegraph

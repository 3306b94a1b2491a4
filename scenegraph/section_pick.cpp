#include "scenegraph/section_pick.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <system_error>
#include <utility>

#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPath.h>
#include <Inventor/SoPickedPoint.h>
#include <Inventor/actions/SoRayPickAction.h>
#include <Inventor/lists/SoPickedPointList.h>
#include <Inventor/nodes/SoLOD.h>
#include <Inventor/nodes/SoSeparator.h>

#include "reconstruction/analysis/report_writer.h"
#include "reconstruction/mesh/lod_levels.h"
#include "scenegraph/main_thread.h"
#include "scenegraph/well_scene.h"

namespace caliper3d::scenegraph {

namespace {

// Which well, segment and level a picked path runs through:
//   well root, segment group, spans ..., segment SoLOD, level node [, part SoLOD, full | reduced]
// or, where a span draws its merged mesh, ..., span SoLOD, merged mesh (WellScene,
// makeSegmentLod, makeLevelNode). The path line's picks go elsewhere.
struct PathHit {
    std::size_t well = 0;
    std::size_t segment = 0;
    int level = 0;
    bool inParts = false;
    bool reducedPart = false;
    int spanDepth = 0;  // > 0: a span's merged mesh, rows [firstRow, lastRow]
    std::size_t firstRow = 0;
    std::size_t lastRow = 0;
};

std::optional<PathHit> wallOf(const SoPath* path, const std::vector<PickableWell>& wells) {
    const int n = path->getLength();
    for (int i = 0; i + 1 < n; ++i) {
        for (std::size_t w = 0; w < wells.size(); ++w) {
            const WellScene& scene = *wells[w].scene;
            if (path->getNode(i) != scene.root()) continue;
            if (path->getNode(i + 1) != scene.segmentGroup()) return std::nullopt;
            for (int j = i + 2; j + 1 < n; ++j) {
                const SoNode* node = path->getNode(j);
                if (const auto segment = scene.segmentOfLod(node)) {
                    PathHit hit;
                    hit.well = w;
                    hit.segment = *segment;
                    // A segment's SoLOD holds its levels from the finest it holds on.
                    hit.level = scene.heldFrom(hit.segment) + path->getIndex(j + 1);
                    if (j + 3 < n && path->getNode(j + 2)->isOfType(SoLOD::getClassTypeId())) {
                        hit.inParts = true;
                        hit.reducedPart = path->getIndex(j + 3) == 1;
                    }
                    return hit;
                }
                if (const auto span = scene.spanOfLod(node)) {
                    if (path->getIndex(j + 1) != 1) continue;  // its children: further down
                    PathHit hit;
                    hit.well = w;
                    hit.spanDepth = span->depth;
                    hit.firstRow = span->firstRow;
                    hit.lastRow = span->lastRow;
                    return hit;
                }
            }
            return std::nullopt;
        }
    }
    return std::nullopt;
}

// The segment holding `row` (segments share their end rows: the first that holds it).
std::size_t segmentOfRow(const reconstruction::WellGeometry& g, std::size_t row) {
    std::size_t lo = 0, hi = g.segmentCount();
    while (lo + 1 < hi) {
        const std::size_t mid = (lo + hi) / 2;
        if (g.segmentRows(mid).first <= row)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

void checkWells(const std::vector<PickableWell>& wells) {
    for (const PickableWell& w : wells)
        if (!w.scene || !w.geometry ||
            (w.wholeRows
                 ? w.wholeRows->size() != w.geometry->table().rowCount()
                 : !w.analysis || w.analysis->sections.size() != w.geometry->table().rowCount()))
            throw std::invalid_argument(
                "pickSection: every well needs its scene, its geometry and that geometry's "
                "analysis");
}

// The nearest wall point among the action's picks (all of them, nearest first: the path line
// or another well's wall may lie in front).
std::optional<SectionPick> nearestWall(SoRayPickAction& action, SoNode* root,
                                       const std::vector<PickableWell>& wells) {
    action.setPickAll(TRUE);
    action.apply(root);
    const SoPickedPointList& picked = action.getPickedPointList();
    for (int k = 0; k < picked.getLength(); ++k) {
        const SoPickedPoint* point = picked[k];
        const std::optional<PathHit> hit = wallOf(point->getPath(), wells);
        if (!hit) continue;
        const PickableWell& well = wells[hit->well];
        SectionPick out;
        out.well = hit->well;
        out.wellName = well.name;
        out.segment = hit->segment;
        out.level = hit->level;
        out.inParts = hit->inParts;
        out.reducedPart = hit->reducedPart;
        out.spanDepth = hit->spanDepth;
        const SbVec3f& p = point->getPoint();
        out.point = glm::vec3(p[0], p[1], p[2]);
        auto [firstRow, lastRow] = hit->spanDepth > 0 ? std::pair(hit->firstRow, hit->lastRow)
                                                      : well.geometry->segmentRows(hit->segment);
        if (hit->spanDepth > 0 && well.wholeRows) {  // the rows held within the span's
            const std::vector<std::size_t>& held = *well.wholeRows;
            firstRow = static_cast<std::size_t>(
                std::lower_bound(held.begin(), held.end(), firstRow) - held.begin());
            lastRow = static_cast<std::size_t>(std::upper_bound(held.begin(), held.end(), lastRow) -
                                               held.begin());
            lastRow = std::max(firstRow, lastRow > 0 ? lastRow - 1 : 0);
        }
        out.wall = reconstruction::locateWallPoint(*well.geometry, firstRow, lastRow,
                                                   glm::dvec3(out.point));
        if (hit->spanDepth > 0) {
            out.segment = segmentOfRow(*well.geometry, out.wall.row);
            out.level =
                static_cast<int>(reconstruction::lodPyramid(well.geometry->options()).size());
        }
        if (well.analysis)
            out.section = well.analysis->sections[out.wall.row];
        else
            out.analysed = false;
        return out;
    }
    return std::nullopt;
}

// The report's columns that a section without data leaves empty (its position, path and bit
// size stay known; docs/analysis.md, "Report CSV").
bool isMeasurement(const std::string& column) {
    static const char* const kMeasurements[] = {"dmin_mm",
                                                "dmax_mm",
                                                "ellipticity",
                                                "major_azimuth_deg",
                                                "area_mm2",
                                                "centre_offset_mm",
                                                "equivalent_diameter_mm",
                                                "major_from_high_side_deg",
                                                "centre_offset_azimuth_deg",
                                                "repaired_arms"};
    for (const char* m : kMeasurements)
        if (column == m) return true;
    return false;
}

std::string fixed(double v, int decimals) {
    char buf[64];
    const auto result = std::to_chars(buf, buf + sizeof buf, v == 0.0 ? 0.0 : v,
                                      std::chars_format::fixed, decimals);
    return result.ec == std::errc() ? std::string(buf, result.ptr) : std::string();
}

// A value of the pick's own: empty when undefined, as the report writes it.
std::string valueOf(double v, int decimals) {
    return std::isfinite(v) ? fixed(v, decimals) : std::string();
}

}  // namespace

std::optional<SectionPick> pickSection(SoNode* root, const SbViewportRegion& viewport,
                                       const SbVec2s& pixel,
                                       const std::vector<PickableWell>& wells) {
    assertMainThread("pickSection");
    checkWells(wells);
    SoRayPickAction action(viewport);
    // Through the pixel's centre, where the picture's sample is taken.
    const SbVec2s origin = viewport.getViewportOriginPixels();
    const SbVec2s size = viewport.getViewportSizePixels();
    action.setNormalizedPoint(SbVec2f((static_cast<float>(pixel[0] - origin[0]) + 0.5f) / size[0],
                                      (static_cast<float>(pixel[1] - origin[1]) + 0.5f) / size[1]));
    return nearestWall(action, root, wells);
}

std::optional<SectionPick> pickSection(SoNode* root, const SbViewportRegion& viewport,
                                       const SbVec3f& start, const SbVec3f& direction,
                                       const std::vector<PickableWell>& wells) {
    assertMainThread("pickSection");
    checkWells(wells);
    SoRayPickAction action(viewport);
    // From `start` on only: without a near distance Coin picks behind the start too.
    action.setRay(start, direction, 0.0f);
    return nearestWall(action, root, wells);
}

std::string formatSectionPick(const SectionPick& pick) {
    const bool noData = pick.section.cls == reconstruction::BoreholeClass::NoData;
    std::string out;
    auto line = [&out](const std::string& key, const std::string& value) {
        out += key;
        out += '=';
        out += value;
        out += '\n';
    };
    line("well", std::to_string(pick.well));
    line("well_name", pick.wellName);
    line("section", std::to_string(pick.wall.row));
    line("segment", std::to_string(pick.segment));
    line("level", std::to_string(pick.level));
    if (pick.inParts) line("part", pick.reducedPart ? "reduced" : "every_section");
    if (pick.spanDepth > 0) line("span_depth", std::to_string(pick.spanDepth));
    line("angle_from_high_side_deg", valueOf(pick.wall.fromHighSide_deg, 2));
    line("angle_azimuth_deg", valueOf(pick.wall.azimuth_deg, 2));
    line("angle_from_arm1_deg", valueOf(pick.wall.fromArm1_deg, 2));
    line("radius_mm", noData ? "no_data" : valueOf(pick.wall.radius_mm, 2));
    line("scene_point_m",
         fixed(pick.point.x, 4) + ',' + fixed(pick.point.y, 4) + ',' + fixed(pick.point.z, 4));
    for (const auto& [column, value] : reconstruction::sectionReportFields(pick.section))
        line(column, noData && value.empty() && isMeasurement(column) ? "no_data" : value);
    return out;
}

}  // namespace caliper3d::scenegraph

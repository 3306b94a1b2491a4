#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Inventor/SbVec2s.h>
#include <Inventor/SbVec3f.h>
#include <glm/vec3.hpp>

#include "reconstruction/analysis/well_analysis.h"
#include "reconstruction/mesh/wall_point.h"
#include "reconstruction/well_geometry.h"

class SbViewportRegion;
class SoNode;

namespace caliper3d::scenegraph {

class WellScene;

// A well a pick can land on: its nodes, the geometry they were built from (segment i of the
// scene is geometry.segmentRows(i)), the report's analysis of that geometry
// (reconstruction::analyseWell) and the name to show.
struct PickableWell {
    const WellScene* scene = nullptr;
    const reconstruction::WellGeometry* geometry = nullptr;
    const reconstruction::WellAnalysis* analysis = nullptr;
    std::string name;
    // A well held lean (docs/architecture.md, "A field held lean"): `geometry` holds these
    // rows of the whole well its nodes were built from, increasing, and there is no analysis.
    // A pick on it finds the row held nearest the point hit, and no report's row.
    const std::vector<std::size_t>* wholeRows = nullptr;
};

// What a ray met on the wall (docs/architecture.md, "Picking").
struct SectionPick {
    std::size_t well = 0;  // index into the wells given
    std::string wellName;
    std::size_t segment = 0;
    // The pyramid level drawn where the ray met the wall (reconstruction/mesh/lod_levels.h),
    // and at level 0 cut into parts, whether the part drew its reduced copy.
    // Where a span of the tree drew its merged mesh instead (reconstruction/mesh/lod_tree.h):
    // its depth (0: none), with `level` one past the pyramid's coarsest.
    int level = 0;
    bool inParts = false;
    bool reducedPart = false;
    int spanDepth = 0;
    glm::vec3 point{0.0f};           // where the ray met the wall as drawn (scene frame)
    reconstruction::WallPoint wall;  // the section (row), the angles, the true radius there
    // The report's row for that section (its MD is section.md_m): what `caliper3d report`
    // writes for it. A section without data has class NoData and every measurement NaN.
    reconstruction::SectionResult section;
    // False on a well held lean: `wall` is the row held nearest the point (a row of the
    // geometry given), and `section` is left empty.
    bool analysed = true;
};

// Runs an SoRayPickAction from `root` through `pixel` of `viewport` (Coin's pixels: origin at
// the bottom left, the ray through the pixel's centre, the camera under `root` as when
// drawn) and returns the nearest point where it meets the wall of one of `wells`; nothing
// when it meets no wall (a miss, the path line, or a segment that draws nothing from here).
// Every SoLOD picks the level it draws, so the pick lands on the wall the picture shows.
// Throws std::invalid_argument when a well lacks its geometry, or its analysis where it is not
// held lean. Main thread only.
std::optional<SectionPick> pickSection(SoNode* root, const SbViewportRegion& viewport,
                                       const SbVec2s& pixel,
                                       const std::vector<PickableWell>& wells);
// The same along a ray in the scene frame from `start` towards `direction`; the levels are
// still the ones the camera under `root` sees (SoLOD chooses by the eye, not by the ray).
std::optional<SectionPick> pickSection(SoNode* root, const SbViewportRegion& viewport,
                                       const SbVec3f& start, const SbVec3f& direction,
                                       const std::vector<PickableWell>& wells);

// The pick as `key=value` lines: well, well_name, section (row), segment, level (and part at
// level 0 in parts, span_depth on a span's merged mesh), angle_from_high_side_deg,
// angle_azimuth_deg, angle_from_arm1_deg, radius_mm (the true section at that angle), scene_point_m
// (x,y,z as drawn), then every column of the report's CSV for that section with the report's
// digits. An undefined value is empty, as in the report; a section without data says no_data for
// each measurement. Decimal points whatever the locale.
std::string formatSectionPick(const SectionPick& pick);

}  // namespace caliper3d::scenegraph

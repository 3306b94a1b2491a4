#pragma once

#include <vector>

#include "reconstruction/mesh/mesh.h"
#include "reconstruction/well_geometry.h"

class SoGroup;
class SoLOD;
class SoIndexedTriangleStripSet;
class SoNode;

namespace caliper3d::scenegraph {

// One SoIndexedTriangleStripSet carrying its own SoVertexProperty (positions,
// normals, per-vertex colours when the mesh has them). Main thread only.
SoIndexedTriangleStripSet* makeStripSet(const reconstruction::Mesh& mesh);

// How finely the picture needs the wall: the focal length in pixels (half the viewport
// height over the tangent of half the camera's height angle) and the shape error, in
// pixels, that may show. Level switches follow from it, so they hold at any window size
// and field of view.
//
// The default tolerance is 3 px: against 2 px it draws a quarter fewer triangles looking down
// the 4 km well, and no pixel of the example well's or the 4 km well's pictures differs by
// more than 3 % (docs/benchmarks.md, "Pixel tolerance").
inline constexpr float kDefaultPixelTolerance = 3.0f;
struct LodView {
    float focal_px = 966.0f;  // 800 pixels high, 45 degrees
    float pixelTolerance = kDefaultPixelTolerance;
    float visibility_m = 0.0f;  // haze fog: nothing shows beyond this distance (0: no fog)
};
LodView lodViewFor(int viewportHeight_px, float heightAngle_rad,
                   float pixelTolerance = kDefaultPixelTolerance);

// The distances (scene units, metres, eye to the segment's centre) at which a segment
// switches from pyramid level i to level i + 1, for every level of its pyramid; past the
// last the segment draws nothing (its wall is under `pixelTolerance` pixels wide, and the
// path line shows the well). A level's shape error must project under the tolerance:
// distance >= error x focal / tolerance, plus the segment's radius (the wall may be that
// much nearer than the centre). Never decreasing; with fog, none past the fog's visibility
// (plus the radius), where a wall would be drawn in the fog's colour only.
std::vector<float> lodSwitchDistances(const reconstruction::SegmentMesh& segment,
                                      const LodView& view);

// The pyramid level a segment should show at `distance` (levelError_mm.size() = nothing).
int lodLevelAt(const std::vector<float>& switchDistances, float distance);

// The distance (eye to the part's centre) past which a part of level 0 shows its reduced
// copy: the segment's partError_mm projected under the tolerance, plus the part's radius.
float partSwitchDistance(const reconstruction::DetailPart& part, float partError_mm,
                         const LodView& view);

// Level `level` of a segment (level >= segment.firstLevel) as a node: a strip set, or for
// level 0 cut into parts, a group of one SoLOD per part { every section, reduced copy }
// whose strip sets share level 0's vertices. Main thread only.
SoNode* makeLevelNode(const reconstruction::SegmentMesh& segment, int level, const LodView& view);
// Resets the part switches of a level-0 node made by makeLevelNode for a new view (`shape`
// needs only its parts' centres and radii and partError_mm). Main thread only.
void setPartRanges(SoNode* levelNode, const reconstruction::SegmentMesh& shape,
                   const LodView& view);

// `shape` under a separator of its own whose render cache Coin may compile (a display list
// drawn in one call instead of a vertex at a time), or `shape` itself, as
// renderCachingWanted() says. Every static mesh of a well goes through here: an SoLOD forbids
// caching above it, so a cache can only sit below the level switches.
SoNode* cacheableShape(SoNode* shape);
// renderCachingWanted() is in scenegraph/render_caching.h: on with a hardware OpenGL driver,
// off on llvmpipe (or as CALIPER3D_RENDER_CACHING says).

// A segment as an SoLOD: its levels (segment.firstLevel on), finest first, then an empty
// group, switching at lodSwitchDistances. Main thread only.
SoLOD* makeSegmentLod(const reconstruction::SegmentMesh& segment, const LodView& view = {});

}  // namespace caliper3d::scenegraph

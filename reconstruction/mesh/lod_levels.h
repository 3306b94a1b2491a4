#pragma once

#include <cstddef>
#include <limits>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "reconstruction/mesh/mesh.h"

namespace caliper3d::reconstruction {

class WellGeometry;
class PeriodicSplineSampler;
struct GeometryOptions;

// One level of a segment's level-of-detail pyramid (docs/architecture.md, "Level of detail").
struct LodLevel {
    double tolerance_mm = 0.0;  // a section is left out while the sections kept on either side
                                //   interpolate every one of its arms within this (shape error)
    double maxSpacing_m = 0.0;  // kept sections are never further apart (0: keep every section)
    int points = 0;             // samples of the closed spline per section; 0: the pads' N-gon
};

// The pyramid, finest first: level 0 every section with GeometryOptions::splinePoints points;
// each next level a coarser shape tolerance (GeometryOptions::shapeTolerance_mm x 1, 4, 16),
// a longer longest spacing and fewer points, down to the raw N-gon. A new level is one more
// entry here; the scene graph adds an empty last level of its own (nothing drawn once a
// segment is under a pixel or two wide, where the path line shows the well).
std::vector<LodLevel> lodPyramid(const GeometryOptions& options);

// Levels built for the whole well up front; finer ones are built on demand, near the camera.
inline constexpr int kFirstCoarseLevel = 2;
// Up front in a field of wells (render of several wells; in the window every well after the
// first): the pads' N-gon, a ring a metre at most. A field seen whole draws its spans' merged
// meshes, and what a camera needs finer is built for it (scenegraph::refineForCamera in a
// picture, the detail worker in the window), so the finer coarse level, eight times the
// vertices, would be built for every segment of every well and drawn for none.
inline constexpr int kFieldFirstCoarseLevel = 3;

// Rows a level keeps among [first, last]: both ends, every measured row next to a no-data
// row (so the wall reaches a gap's edges at every level), and otherwise a row only where
// leaving it out would move one of its arms by more than tolerance_mm from the straight line
// (in depth) between the rows kept on either side, or spread kept rows over maxSpacing_m.
// One pass, a slope corridor per arm: the rows between two kept rows are checked as the
// corridor narrows (the swing-door test), never one at a time against every pair.
std::vector<std::size_t> decimatedRows(const WellGeometry& geometry, std::size_t first,
                                       std::size_t last, const LodLevel& level);

// Levels [from, to) of one segment's pyramid (to clipped to the pyramid's size). Rows
// without data are a gap in the wall at every level. Reads only the geometry's public,
// immutable state, so any thread may build any segment.
SegmentMesh buildSegmentLevels(const WellGeometry& geometry, std::size_t segment, int from, int to);
// What levels [from, to) of a segment keep (from at least 1), decided on the whole well: the
// rows of each level (the swing-door test reads undrawn radii, so they do not depend on the
// exaggeration) and what the levels' errors and bounds need of the rows left out.
struct SegmentPlan {
    std::size_t index = 0;
    std::size_t firstRow = 0, lastRow = 0;
    int firstLevel = 1;
    double maxRadius_mm = 0.0;  // largest knot value, undrawn
    std::size_t fullDetailTriangles = 0;
    std::vector<std::vector<std::size_t>> levelRows;  // per level, from firstLevel
};
// `knots`: where given, the knots of the segment's rows, row after row from its first
// (WellGeometry::sectionKnots; zeros for a row without data), computed once for several plans.
SegmentPlan planSegmentLevels(const WellGeometry& whole, std::size_t segment, int from, int to,
                              const double* knots = nullptr);
// Those levels drawn from `drawn`: the whole well, or a copy holding at least the planned rows
// and every row without data between them (wholeRows[i] the whole well's row that is drawn's
// row i; null: drawn is the whole well). The same meshes buildSegmentLevels(whole restyled
// alike, segment, from, to) gives; row numbers stay the whole well's.
SegmentMesh finishSegmentLevels(const WellGeometry& drawn, const SegmentPlan& plan,
                                const std::vector<std::size_t>* wholeRows);
// An axis-aligned box in the scene frame; empty (lo above hi) until extended.
struct Box3 {
    glm::vec3 lo{std::numeric_limits<float>::max()};
    glm::vec3 hi{std::numeric_limits<float>::lowest()};
    bool empty() const { return lo.x > hi.x; }
    void extend(const glm::vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void extend(const Box3& box) {
        if (box.empty()) return;
        extend(box.lo);
        extend(box.hi);
    }
};
// The box of every point the strips of finishSegmentLevels(drawn, plan, wholeRows) draw, found
// without building the meshes (a segment made when a camera comes near is bounded by it
// until then).
Box3 plannedSegmentBox(const WellGeometry& drawn, const SegmentPlan& plan,
                       const std::vector<std::size_t>* wholeRows);
// Drawn's row for a whole well's `row` (wholeRows as above; the row must be among them).
std::size_t drawnRow(const std::vector<std::size_t>* wholeRows, std::size_t row);

// Every level.
SegmentMesh buildSegmentMesh(const WellGeometry& geometry, std::size_t segment);
// The levels built up front, `firstLevel` on.
SegmentMesh buildCoarseSegment(const WellGeometry& geometry, std::size_t segment,
                               int firstLevel = kFirstCoarseLevel);

// The rings of `rows` (increasing) joined by closed strips wherever every row between two of
// them is measured (a no-data interval is a gap in the wall). The first and last rows get the
// full spline (GeometryOptions::splinePoints samples), so any two meshes that end on the same
// row meet without a crack; the others get `points` samples (0: the pads' N-gon). What every
// pyramid level and every span of the level-of-detail tree (lod_tree.h) draws.
Mesh buildRingMesh(const WellGeometry& geometry, const std::vector<std::size_t>& rows, int points);

// A ring of `radii_mm` at equal angles from arm 1 in its section's plane (x along arm 1, y
// 90 degrees clockwise), millimetres, drawn `exaggeration` times larger about the centroid of
// its area as every level draws it.
void drawnRing(const std::vector<double>& radii_mm, double exaggeration,
               std::vector<glm::dvec2>& out);
// The unit vectors drawnRing draws `points` radii along (cos, sin of equal angles from arm 1),
// kept per thread.
const std::vector<glm::dvec2>& unitRing(std::size_t points);
// The centroid of a ring's area (shoelace), about which drawnRing draws it larger; the tool
// axis (0, 0) when the ring has no area.
glm::dvec2 ringCentroid(const std::vector<glm::dvec2>& ring);

// The largest distance, drawn, in millimetres, from a point of `row`'s full-detail ring to the
// ring a coarser level draws for it: the spline sampled by `level`, or the pads' polygon when
// `level` is null. Measured, where chordError assumes a circle: a breakout's ring strays
// further from its polygon than a round hole's. 0 for a row without data.
double ringError_mm(const WellGeometry& geometry, std::size_t row,
                    const PeriodicSplineSampler* level);

// The largest chord error of a closed polygon of `points` vertices on a circle of `radius`.
double chordError(double radius, int points);

// The wall of one section as the finest level draws it: its closed spline's points in the
// scene frame, radial exaggeration included (what the window outlines at the current depth).
// Empty for a row without data.
std::vector<glm::vec3> sectionRing(const WellGeometry& geometry, std::size_t row);

}  // namespace caliper3d::reconstruction

#pragma once

#include <atomic>
#include <cstddef>
#include <utility>
#include <vector>

#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/mesh/mesh.h"

namespace caliper3d::reconstruction {

class WellGeometry;
struct GeometryOptions;

// The level-of-detail tree over a well's segments (docs/architecture.md, "Level of detail"):
// a span of depth 1 groups kLodTreeFanOut consecutive segments, a span of depth d groups
// kLodTreeFanOut spans of depth d - 1, and the deepest span, the root, holds the whole well.
// Each span carries one merged mesh of its whole length, drawn in place of its children once
// its shape error projects under the pixel tolerance, so a kilometre seen from afar is a few
// strips, not a thousand segments.
inline constexpr std::size_t kLodTreeFanOut = 16;

// The merged mesh of one span.
struct SpanMesh {
    int depth = 1;
    std::size_t index = 0;         // among the spans of its depth
    std::size_t firstSegment = 0;  // segments [firstSegment, lastSegment]
    std::size_t lastSegment = 0;
    std::size_t firstRow = 0;  // rows [firstRow, lastRow]: its first segment's first row to its
    std::size_t lastRow = 0;   //   last segment's last row
    glm::vec3 centre{0.0f};    // scene frame, for LOD distances
    float radius = 0.0f;       // bounding sphere radius about centre, metres
    float maxRadius_m = 0.0f;  // largest drawn radius of the wall (SegmentMesh::maxRadius_m)
    // The largest distance, in drawn millimetres, between this mesh and the wall its finest
    // level draws: the rows it leaves out, the points per ring and the straight path between
    // the rows it keeps.
    float error_mm = 0.0f;
    Mesh mesh;
};

// Depth of the root over `segments` segments: the smallest d >= 1 with kLodTreeFanOut^d >=
// segments.
int lodTreeDepth(std::size_t segments);
// Spans of depth `depth` over `segments` segments.
std::size_t spanCount(int depth, std::size_t segments);
// The segments [first, last] of span `index` of depth `depth`.
std::pair<std::size_t, std::size_t> spanSegments(int depth, std::size_t index,
                                                 std::size_t segments);

// What a span of depth `depth` keeps: the pyramid's coarsest shape tolerance times 2 per
// depth, its longest spacing (or the segment length) times 4 per depth, and fewer spline
// points per ring (the pads' N-gon for tools of up to 8 knots, else half as many samples per
// depth, at least 6). Long spacing, not a loose tolerance, is what a span saves: a drawn
// wall exaggerated a hundred times must keep its shape to metres where it is seen whole.
LodLevel spanLevel(const GeometryOptions& options, int knots, int depth);

// Every span of the tree, depth 1 first and each depth in index order. A span of depth 1
// decimates every measured row of its segments; a deeper one decimates the rows its children
// kept (the same swing-door test, lod_levels.h), so its error is its own tolerance plus its
// children's, never measured against fewer rows than exist. Reads only the geometry's public,
// immutable state (any thread). Returns what it has built when `cancel` is set.
std::vector<SpanMesh> buildSpanMeshes(const WellGeometry& geometry,
                                      const std::atomic<bool>* cancel = nullptr);

// What a span keeps, decided on the whole well before any exaggeration is chosen
// (planCoarseMeshes): the swing-door test reads undrawn radii, so the rows a span keeps do
// not depend on how it is drawn, and only the pads' part of its error does. That part is
// measured at each of the plan's exaggerations, where the rows it leaves out are at hand.
struct SpanPlan {
    int depth = 1;
    std::size_t index = 0;
    std::size_t firstSegment = 0, lastSegment = 0;
    std::size_t firstRow = 0, lastRow = 0;
    std::vector<std::size_t> rows;  // kept, increasing (the whole well's rows)
    // Per exaggeration of the plan: the largest drawn distance (mm) between a row's pads'
    // polygon and the straight line between the kept rows' (this span's and its children's).
    std::vector<double> padError_mm;
    // At any other exaggeration F: at most padCentroid_mm + F padShape_mm (the distance of the
    // polygons' centroids plus F times that of the points about them).
    double padCentroid_mm = 0.0, padShape_mm = 0.0;
    double centreDeviation_m = 0.0;  // the straight path between kept rows from the rows' centres
    double maxRadius_mm = 0.0;       // largest knot value, undrawn
    double reach_m = 0.0;            // the furthest row centre from the span's centre
};

// A well's meshes built up front: every segment's levels from `firstLevel` on
// (buildCoarseSegment) and every span (buildSpanMeshes).
struct CoarseMeshes {
    std::vector<SegmentMesh> segments;
    std::vector<SpanMesh> spans;
};

// What a well's coarse meshes keep (SegmentPlan, SpanPlan), decided on the whole well for the
// radial exaggerations listed, so that the meshes can be built later from only the rows kept
// (a field held lean: docs/architecture.md) once the field's exaggeration is chosen.
// `firstLevel` is at least 1: level 0 keeps every row.
struct CoarsePlan {
    int firstLevel = kFirstCoarseLevel;
    std::vector<double> exaggerations;
    std::vector<SegmentPlan> segments;
    std::vector<SpanPlan> spans;  // depth 1 first, each depth in index order
    // Every row a mesh draws or steps over (a row without data stops a strip), increasing.
    std::vector<std::size_t> rows() const;
};
CoarsePlan planCoarseMeshes(const WellGeometry& whole, int firstLevel,
                            std::vector<double> exaggerations, int threads = 2);

// The meshes `plan` describes, drawn from `drawn` at its own exaggeration and colours: the
// whole well the plan was made on, or a copy holding the plan's rows (wholeRows[i] the whole
// well's row that is drawn's row i; null: drawn is the whole well). Rows and errors are those
// buildCoarseMeshes(whole restyled alike, firstLevel) gives, when the exaggeration is one
// the plan lists.
CoarseMeshes buildCoarseMeshes(const WellGeometry& drawn, const CoarsePlan& plan,
                               const std::vector<std::size_t>* wholeRows = nullptr,
                               int threads = 2);

// The spans' meshes only of buildCoarseMeshes(drawn, plan, wholeRows): a scene that builds
// a segment's levels when a camera comes near builds those with finishSegmentLevels.
std::vector<SpanMesh> buildPlannedSpans(const WellGeometry& drawn, const CoarsePlan& plan,
                                        const std::vector<std::size_t>* wholeRows = nullptr,
                                        int threads = 2);

// planCoarseMeshes at the geometry's own exaggeration, then buildCoarseMeshes. Reads only the
// geometry, so any thread may build it; it uses two threads of its own (the machine's two
// cores).
CoarseMeshes buildCoarseMeshes(const WellGeometry& geometry, int firstLevel = kFirstCoarseLevel);

}  // namespace caliper3d::reconstruction

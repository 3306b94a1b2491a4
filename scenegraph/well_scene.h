#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include <Inventor/nodes/SoSeparator.h>

#include "reconstruction/mesh/lod_tree.h"
#include "reconstruction/well_geometry.h"
#include "scenegraph/node_ref.h"
#include "scenegraph/segment_node_builder.h"

class SoCoordinate3;
class SoGroup;
class SoNode;
class SoLineSet;
class SoLOD;

namespace caliper3d::scenegraph {

// How far the coarser copy of a well's path line may stray from the line (WellScene::setPath).
inline constexpr float kPathTolerance_m = 0.25f;

// When a well's segment nodes are made: all at once, or a span's sixteen when a camera first
// comes near enough for the span to show them (WellScene::makeSegmentNodesNear), their coarse
// levels built then. Until then the span shows its merged mesh. A picture of a field seen
// whole draws spans only, so a hundred wells of a thousand segments each need none of their
// 100,000 segment meshes and nodes (docs/architecture.md, "Segments made when near").
enum class SegmentNodes { now, whenNear };

// A finer level a segment should show from where the camera is (and does not hold yet).
struct DetailRequest {
    std::size_t segment = 0;
    int level = 0;          // the finest pyramid level wanted
    int heldFrom = 0;       // the finest level held now: build [level, heldFrom)
    float distance = 0.0f;  // eye to the segment's centre, metres
};

// The nodes of one well: shape hints and material, the path as a line, and the segments in a
// level-of-detail tree (reconstruction/mesh/lod_tree.h), under one separator. Main thread only.
//
//   root: SoSeparator
//     SoShapeHints (two-sided lighting: the hole is seen from inside too)
//     SoMaterial
//     path: SoSeparator { SoDrawStyle, SoCoordinate3, SoLineSet }
//     segments: SoSeparator { the root span }
//   a span: SoSeparator (culled outside the view) { SoLOD {
//       SoGroup { its 16 segments' SoLODs (depth 1) or its 16 child spans },
//       the merged mesh of its whole length, an empty group } }
//
// Segments come with their coarse levels (reconstruction::kFirstCoarseLevel on); finer ones
// are added near the camera (attachFinerLevels) and dropped again, least recently wanted
// first, when their triangles pass a budget (evictFineLevels). The coarser levels stay in
// the SoLOD meanwhile, so a segment is never missing. A span shows its children until its
// merged mesh arrives (addSpan), then switches to it once its error projects under the pixel
// tolerance, and to nothing once the whole span is under the tolerance wide (the path line
// shows the well). The tree grows a root as segments stream in.
class WellScene {
public:
    WellScene();

    SoSeparator* root() const { return m_root.get(); }
    // The separator holding the tree's root span.
    const SoSeparator* segmentGroup() const { return m_segments; }

    // Draws the well path (decimated to about one point per `spacing_m`), and a copy within
    // kPathTolerance_m of it where it is far enough for that to be under the pixel tolerance.
    void setPath(const reconstruction::WellGeometry& geometry, double spacing_m = 1.0);
    // Draws the path on past what is drawn, to these points (a streamed load's
    // reconstruction::LoadStretch::path, in order).
    void extendPath(const std::vector<glm::vec3>& points);
    // Segments arrive in order (segment.index = segmentCount()).
    void addSegment(const reconstruction::SegmentMesh& segment);
    // The merged mesh of a span whose segments are here (others are ignored).
    void addSpan(const reconstruction::SpanMesh& span);
    // Path, every segment's coarse levels (`firstLevel` on) and every span, built here on the
    // calling (main) thread.
    void buildAll(const reconstruction::WellGeometry& geometry,
                  int firstLevel = reconstruction::kFirstCoarseLevel);
    // The same from meshes built elsewhere (reconstruction::buildCoarseMeshes, on a worker).
    void attachAll(const reconstruction::WellGeometry& geometry,
                   const reconstruction::CoarseMeshes& meshes);
    // Segments made when a camera comes near (SegmentNodes::whenNear): how many, their
    // triangles at full detail, and what builds segment s's coarse levels (called here, on the
    // main thread, when its span is first wanted).
    // Each segment's box (reconstruction::plannedSegmentBox; none: not given) bounds its span
    // meanwhile, so that what frames and culls a picture is what the segments will be.
    struct WaitingSegments {
        std::size_t count = 0;
        std::size_t fullDetailTriangles = 0;
        std::function<reconstruction::SegmentMesh(std::size_t)> build;
        std::vector<reconstruction::Box3> boxes;
    };
    // The path and every span's merged mesh now, the segments when near (a span without a
    // merged mesh makes its segments now).
    void attachAll(const reconstruction::WellGeometry& geometry,
                   const std::vector<reconstruction::SpanMesh>& spans, WaitingSegments segments);
    // Path and every level of every segment (tests; a whole well at full detail is large).
    void buildAllLevels(const reconstruction::WellGeometry& geometry);

    // Computes the bounding boxes the spans' separators cache, where a change left them
    // invalid: Coin culls a separator only by a cached box, and a render action never makes
    // one. Called after building and after each change of held levels; cheap where nothing
    // changed (the valid caches answer).
    void cacheBounds();

    // Switch distances for a new viewport or field of view (every SoLOD's range).
    void setLodView(const LodView& view);

    // Makes the nodes of the segments waiting (SegmentNodes::whenNear) under every span that
    // should show its segments seen from `eye` (scene frame), and caches the bounds they
    // change.
    void makeSegmentNodesNear(const glm::vec3& eye);
    // Segments that should show a finer level than they hold, seen from `eye` (scene
    // frame), nearest first. Marks every segment wanted at its finer levels as used now.
    // First makes the segment nodes near `eye` (makeSegmentNodesNear).
    std::vector<DetailRequest> wantedDetail(const glm::vec3& eye);
    // Puts levels [finer.firstLevel, held) in front of the segment's levels.
    void attachFinerLevels(const reconstruction::SegmentMesh& finer);
    // Drops the finer-than-coarse levels of segments not wanted now, least recently wanted
    // first, until those held hold at most `budgetTriangles`. Returns the segments dropped.
    std::size_t evictFineLevels(std::size_t budgetTriangles);
    // The segments holding finer-than-coarse levels that the last wantedDetail did not want:
    // how many wantedDetail calls ago each was last wanted, and its fine triangles. With
    // dropFineLevels, what a budget shared by several wells evicts from (DetailLoader).
    struct IdleDetail {
        std::size_t segment = 0;
        std::uint64_t idleFor = 0;
        std::size_t triangles = 0;
    };
    std::vector<IdleDetail> idleDetail() const;
    void dropFineLevels(std::size_t segment);

    std::size_t segmentCount() const { return m_records.size(); }
    // Segments whose node is made (segmentCount() less those waiting: SegmentNodes).
    std::size_t segmentNodes() const { return m_segmentOfLod.size(); }
    // Depth of the root span (0 before the first segment) and spans holding their merged mesh.
    int treeDepth() const { return m_depth; }
    std::size_t mergedSpans() const { return m_mergedSpans; }

    // Picking: the segment whose SoLOD `node` is; the rows and depth of the span whose SoLOD
    // `node` is.
    std::optional<std::size_t> segmentOfLod(const SoNode* node) const;
    struct SpanRows {
        int depth = 0;
        std::size_t firstSegment = 0;
        std::size_t lastSegment = 0;
        std::size_t firstRow = 0;
        std::size_t lastRow = 0;
    };
    std::optional<SpanRows> spanOfLod(const SoNode* node) const;
    // Triangles of every segment at full detail (level 0), counted or estimated from the
    // coarse level's rows when level 0 is not built.
    std::size_t fullDetailTriangles() const { return m_fullTriangles; }
    // Triangles held in finer-than-coarse levels now.
    std::size_t fineTriangles() const { return m_fineTriangles; }
    int heldFrom(std::size_t segment) const { return m_records[segment].heldFrom; }

private:
    struct Record {
        SoLOD* lod = nullptr;  // null while it waits (SegmentNodes::whenNear)
        glm::vec3 centre{0.0f};
        std::vector<float> switchDistances;
        int heldFrom = 0;    // finest level held
        int coarseFrom = 0;  // the first level it arrived with
        std::size_t fineTriangles = 0;
        std::uint64_t lastWanted = 0;
        reconstruction::SegmentMesh
            shape;  // radius, level errors and part shapes only, for the switch distances
    };
    struct Span {
        SoSeparator* separator = nullptr;
        SoLOD* lod = nullptr;
        SoGroup* children = nullptr;
        bool merged = false;       // holds its merged mesh (and the empty level after it)
        bool segmentsMade = true;  // depth 1: its segments' nodes are made (SegmentNodes)
        glm::vec3 centre{0.0f};
        float radius = 0.0f;
        float error_mm = 0.0f;
        float maxRadius_m = 0.0f;
        std::size_t firstSegment = 0;
        std::size_t lastSegment = 0;
        std::size_t firstRow = 0;
        std::size_t lastRow = 0;
    };
    // Puts a segment's place in the tree, its node not made yet (lod null).
    void addRecord();
    // Makes segment `index`'s node from its coarse levels.
    void makeSegmentNode(std::size_t index, const reconstruction::SegmentMesh& segment);
    // Makes the nodes of the segments of depth-1 span `index` that wait.
    void makeSegmentNodes(std::size_t index);
    void setRanges(Record& record);
    // The distances (eye to its centre) from which a span shows its merged mesh instead of
    // its children, and from which nothing (its SoLOD's first range is 0 instead while its
    // segments wait).
    std::pair<float, float> spanSwitchDistances(const Span& span) const;
    void setSpanRanges(Span& span) const;
    // Index of span `index` at `depth`, made (and hung under its parent) when missing.
    std::size_t ensureSpan(int depth, std::size_t index);
    // Puts new roots above the tree until it is `depth` deep.
    void growTo(int depth);
    void collectWanted(int depth, std::size_t index, const glm::vec3& eye,
                       std::vector<DetailRequest>& out);
    void makeNodesNear(int depth, std::size_t index, const glm::vec3& eye);
    // Level 0's part centres and radii (not their meshes), for the part switches.
    static void keepPartShapes(Record& record, const reconstruction::SegmentMesh& segment);

    NodeRef<SoSeparator> m_root;
    SoSeparator* m_pathGroup = nullptr;
    SoSeparator* m_segments = nullptr;
    SoCoordinate3* m_pathCoords = nullptr;  // null until a path is drawn
    SoLineSet* m_pathLine = nullptr;
    // A whole path (setPath) is an SoLOD between its line and a coarser copy (null: none).
    SoLOD* m_pathLod = nullptr;
    float m_pathError = 0.0f;  // the coarser copy's largest distance from the line, metres
    float m_pathReach = 0.0f;  // the line's furthest point from the SoLOD's centre
    void setPathRange();
    LodView m_view;
    std::vector<Record> m_records;
    std::vector<std::vector<Span>> m_spans;  // [depth - 1][index]
    int m_depth = 0;
    std::size_t m_mergedSpans = 0;
    std::unordered_map<const SoNode*, std::size_t> m_segmentOfLod;
    std::unordered_map<const SoNode*, std::pair<int, std::size_t>> m_spanOfLod;
    std::size_t m_fullTriangles = 0;
    std::size_t m_fineTriangles = 0;
    std::uint64_t m_tick = 0;
    bool m_boundsStale = false;  // segment nodes made since the bounds were cached
    std::function<reconstruction::SegmentMesh(std::size_t)> m_waiting;  // builds one waiting
};

// A well drawn from its plan with its segments made when near (SegmentNodes::whenNear): every
// span's merged mesh (reconstruction::buildPlannedSpans on `threads`) and the segments waiting,
// each built from `drawn` as `plan` says when its span is first wanted (`wholeRows` as
// reconstruction::buildCoarseMeshes takes it; null: `drawn` is the whole well). Reads only its
// arguments, so any thread may make it; WellScene::attachAll(drawn, spans, waiting) shows it.
struct PlannedWell {
    std::vector<reconstruction::SpanMesh> spans;
    WellScene::WaitingSegments waiting;
};
PlannedWell planWaitingWell(const std::shared_ptr<const reconstruction::WellGeometry>& drawn,
                            const std::shared_ptr<const reconstruction::CoarsePlan>& plan,
                            const std::shared_ptr<const std::vector<std::size_t>>& wholeRows,
                            int threads);

}  // namespace caliper3d::scenegraph

#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <Inventor/nodes/SoSeparator.h>

#include "reconstruction/well_geometry.h"
#include "scenegraph/node_ref.h"
#include "scenegraph/segment_node_builder.h"

class SoCoordinate3;
class SoLineSet;
class SoLOD;

namespace caliper3d::scenegraph {

// A finer level a segment should show from where the camera is (and does not hold yet).
struct DetailRequest {
    std::size_t segment = 0;
    int level = 0;          // the finest pyramid level wanted
    int heldFrom = 0;       // the finest level held now: build [level, heldFrom)
    float distance = 0.0f;  // eye to the segment's centre, metres
};

// The nodes of one well: shape hints and material, the path as a line, and
// one SoLOD per segment, under one separator. Main thread only.
//
//   root: SoSeparator
//     SoShapeHints (two-sided lighting: the hole is seen from inside too)
//     SoMaterial
//     path: SoSeparator { SoDrawStyle, SoCoordinate3, SoLineSet }
//     segments: SoSeparator { SoLOD, SoLOD, ... }
//
// Segments come with their coarse levels (reconstruction::kFirstCoarseLevel on); finer ones
// are added near the camera (attachFinerLevels) and dropped again, least recently wanted
// first, when their triangles pass a budget (evictFineLevels). The coarser levels stay in
// the SoLOD meanwhile, so a segment is never missing.
class WellScene {
public:
    WellScene();

    SoSeparator* root() const { return m_root.get(); }
    // The separator holding one SoLOD per segment, child i being segment i (picking).
    const SoSeparator* segmentGroup() const { return m_segments; }

    // Draws the well path (decimated to about one point per `spacing_m`).
    void setPath(const reconstruction::WellGeometry& geometry, double spacing_m = 1.0);
    // Draws the path on past what is drawn, to these points (a streamed load's
    // reconstruction::LoadStretch::path, in order).
    void extendPath(const std::vector<glm::vec3>& points);
    // Segments arrive in order (segment.index = segmentCount()).
    void addSegment(const reconstruction::SegmentMesh& segment);
    // Path and every segment's coarse levels, built here on the calling (main) thread.
    void buildAll(const reconstruction::WellGeometry& geometry);
    // Path and every level of every segment (tests; a whole well at full detail is large).
    void buildAllLevels(const reconstruction::WellGeometry& geometry);

    // Switch distances for a new viewport or field of view (every SoLOD's range).
    void setLodView(const LodView& view);

    // Segments that should show a finer level than they hold, seen from `eye` (scene
    // frame), nearest first. Marks every segment wanted at its finer levels as used now.
    std::vector<DetailRequest> wantedDetail(const glm::vec3& eye);
    // Puts levels [finer.firstLevel, held) in front of the segment's levels.
    void attachFinerLevels(const reconstruction::SegmentMesh& finer);
    // Drops the finer-than-coarse levels of segments not wanted now, least recently wanted
    // first, until those held hold at most `budgetTriangles`. Returns the segments dropped.
    std::size_t evictFineLevels(std::size_t budgetTriangles);

    std::size_t segmentCount() const { return m_records.size(); }
    // Triangles of every segment at full detail (level 0), counted or estimated from the
    // coarse level's rows when level 0 is not built.
    std::size_t fullDetailTriangles() const { return m_fullTriangles; }
    // Triangles held in finer-than-coarse levels now.
    std::size_t fineTriangles() const { return m_fineTriangles; }
    int heldFrom(std::size_t segment) const { return m_records[segment].heldFrom; }

private:
    struct Record {
        SoLOD* lod = nullptr;
        glm::vec3 centre{0.0f};
        std::vector<float> switchDistances;
        int heldFrom = 0;    // finest level held
        int coarseFrom = 0;  // the first level it arrived with
        std::size_t fineTriangles = 0;
        std::uint64_t lastWanted = 0;
        reconstruction::SegmentMesh
            shape;  // radius, level errors and part shapes only, for the switch distances
    };
    void setRanges(Record& record);
    // Level 0's part centres and radii (not their meshes), for the part switches.
    static void keepPartShapes(Record& record, const reconstruction::SegmentMesh& segment);

    NodeRef<SoSeparator> m_root;
    SoSeparator* m_pathGroup = nullptr;
    SoSeparator* m_segments = nullptr;
    SoCoordinate3* m_pathCoords = nullptr;  // null until a path is drawn
    SoLineSet* m_pathLine = nullptr;
    LodView m_view;
    std::vector<Record> m_records;
    std::size_t m_fullTriangles = 0;
    std::size_t m_fineTriangles = 0;
    std::uint64_t m_tick = 0;
};

}  // namespace caliper3d::scenegraph

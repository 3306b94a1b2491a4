#pragma once

#include <cstddef>
#include <memory>

#include <Inventor/nodes/SoSeparator.h>

#include "reconstruction/well_geometry.h"
#include "scenegraph/node_ref.h"

namespace caliper3d::scenegraph {

// The nodes of one well: shape hints and material, the path as a line, and
// one SoLOD per segment, under one separator. Main thread only.
//
//   root: SoSeparator
//     SoShapeHints (two-sided lighting: the hole is seen from inside too)
//     SoMaterial
//     path: SoSeparator { SoDrawStyle, SoCoordinate3, SoLineSet }
//     segments: SoSeparator { SoLOD, SoLOD, ... }
class WellScene {
public:
    WellScene();

    SoSeparator* root() const { return m_root.get(); }

    // Draws the well path (decimated to about one point per `spacing_m`).
    void setPath(const reconstruction::WellGeometry& geometry, double spacing_m = 1.0);
    void addSegment(const reconstruction::SegmentMesh& segment);
    // Path and every segment, built here on the calling (main) thread.
    void buildAll(const reconstruction::WellGeometry& geometry);

    std::size_t segmentCount() const { return m_segmentCount; }
    std::size_t fullDetailTriangles() const { return m_fullTriangles; }

private:
    NodeRef<SoSeparator> m_root;
    SoSeparator* m_pathGroup = nullptr;
    SoSeparator* m_segments = nullptr;
    std::size_t m_segmentCount = 0;
    std::size_t m_fullTriangles = 0;
};

}  // namespace caliper3d::scenegraph

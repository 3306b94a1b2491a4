#pragma once

#include "reconstruction/mesh/mesh.h"
#include "reconstruction/well_geometry.h"

class SoLOD;
class SoIndexedTriangleStripSet;

namespace caliper3d::scenegraph {

// One SoIndexedTriangleStripSet carrying its own SoVertexProperty (positions,
// normals, per-vertex colours when the mesh has them). Main thread only.
SoIndexedTriangleStripSet* makeStripSet(const reconstruction::Mesh& mesh);

// A segment as an SoLOD: children finest first, switching at distances that
// grow with the segment's size. Main thread only.
SoLOD* makeSegmentLod(const reconstruction::SegmentMesh& segment);

// The distance (scene units, metres) beyond which SoLOD shows level `level`;
// level 0 below lodRange(0).
float lodRange(const reconstruction::SegmentMesh& segment, int level);

}  // namespace caliper3d::scenegraph

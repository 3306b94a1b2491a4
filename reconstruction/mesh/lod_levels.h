#pragma once

#include <cstddef>

#include "reconstruction/mesh/mesh.h"

namespace caliper3d::reconstruction {

class WellGeometry;

// The level-of-detail meshes of one segment of a well (docs/architecture.md, "Data flow"):
//   level 0  every row, the closed spline of GeometryOptions::splinePoints points;
//   level 1  the raw N-gon of the pads, a row every GeometryOptions::coarseSpacing_m;
//   level 2  the raw N-gon, a row every GeometryOptions::coarsestSpacing_m.
// A new level is one more entry here (and one more SoLOD child in scenegraph/). Rows without
// data are a gap in the wall at every level. Reads only the geometry's public, immutable state,
// so any thread may build any segment.
SegmentMesh buildSegmentMesh(const WellGeometry& geometry, std::size_t segment);

}  // namespace caliper3d::reconstruction

#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace caliper3d::reconstruction {
class WellGeometry;
}

class SoNode;

namespace caliper3d::scenegraph {

struct IvExportOptions {
    bool binary = false;
    bool gzip = false;  // zlib compression of the output stream
};

// Writes `scene` as an Open Inventor file with SoWriteAction. Throws
// std::runtime_error naming the file when it cannot be written.
void writeIv(SoNode* scene, const std::string& path, const IvExportOptions& options = {});

// Writes wells at full detail, every level of every segment, streaming: one segment's nodes
// are built, written and freed before the next, so memory holds one segment's, never the
// whole scene's. The file holds, per well, its shape hints, material and path, then one SoLOD
// per segment (SoDB::readAll reads them back under one separator). Returns the segments
// written. Throws std::runtime_error naming the file when it cannot be written.
std::size_t writeIvFullDetail(const std::vector<const reconstruction::WellGeometry*>& wells,
                              const std::string& path, const IvExportOptions& options = {});

// Reads an Open Inventor file with SoDB::readAll; the caller takes a reference.
// Throws std::runtime_error naming the file when it cannot be read.
SoNode* readIv(const std::string& path);

// What a scene holds, counted over every SoIndexedTriangleStripSet (all LOD
// levels included; vertices from each strip set's SoVertexProperty).
struct SceneCounts {
    std::size_t stripSets = 0;
    std::size_t lods = 0;
    std::size_t vertices = 0;
    std::size_t triangles = 0;
};
SceneCounts countScene(SoNode* scene);

}  // namespace caliper3d::scenegraph

#pragma once

#include <cstddef>
#include <string>

class SoNode;

namespace caliper3d::scenegraph {

struct IvExportOptions {
    bool binary = false;
    bool gzip = false;  // zlib compression of the output stream
};

// Writes `scene` as an Open Inventor file with SoWriteAction. Throws
// std::runtime_error naming the file when it cannot be written.
void writeIv(SoNode* scene, const std::string& path, const IvExportOptions& options = {});

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

#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace caliper3d::reconstruction {

// Plain triangle-strip mesh in the scene frame (floats, relative to the local
// origin). Strips are listed in `stripIndices`, each ended by -1, the layout
// of SoIndexedTriangleStripSet::coordIndex.
struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;      // one per position
    std::vector<std::uint32_t> colours;  // optional, one per position, 0xRRGGBBAA
    std::vector<std::int32_t> stripIndices;

    std::size_t triangleCount() const;
    std::size_t stripCount() const;
};

// Appends the closed strip that joins ring A (first vertex firstA) to ring B
// (firstB), each of `points` vertices, in the reference's order
// A0 B0 A1 B1 ... A(m-1) B(m-1) A0 B0, then -1: 2*points triangles.
void appendClosedStrip(std::vector<std::int32_t>& indices, std::int32_t firstA, std::int32_t firstB,
                       int points);

// The same between rings of different vertex counts (a coarse level's ring and the full
// ring a segment ends with): vertices paired by angle, zero-area triangles where one ring
// has no new vertex, so no crack opens between them.
void appendClosedStrip(std::vector<std::int32_t>& indices, std::int32_t firstA, int pointsA,
                       std::int32_t firstB, int pointsB);

// A stretch of a segment's level 0 with a switch of its own (docs/architecture.md, "Level of
// detail"): within a few decimetres of the eye every section is drawn, further away a copy
// that keeps every spline point but only the sections the shape tolerance needs. Seen down
// the hole, sections 2.5 mm apart are under a pixel apart half a metre from the eye, and a
// whole segment's switch cannot tell its near end from its far end.
struct DetailPart {
    std::size_t firstRow = 0;  // rows [firstRow, lastRow], sharing lastRow with the next part
    std::size_t lastRow = 0;
    std::size_t stripBegin = 0;  // level 0's stripIndices [stripBegin, stripEnd) join its rows
    std::size_t stripEnd = 0;
    glm::vec3 centre{0.0f};  // scene frame, for LOD distances
    float radius = 0.0f;     // bounding sphere radius, metres
    Mesh reduced;            // the same ends (full rings), sections kept at the shape tolerance
};

// One segment's meshes: levels firstLevel, firstLevel + 1, ... of its pyramid
// (reconstruction/mesh/lod_levels.h), finest first.
struct SegmentMesh {
    std::size_t index = 0;
    std::size_t firstRow = 0;  // rows [firstRow, lastRow], sharing lastRow with the next segment
    std::size_t lastRow = 0;
    double top_m = 0.0;
    double bottom_m = 0.0;
    glm::vec3 centre{0.0f};               // scene frame, for LOD distances
    float radius = 0.0f;                  // bounding sphere radius, scene units (metres)
    float maxRadius_m = 0.0f;             // largest drawn radius of the wall
    int firstLevel = 0;                   // pyramid level of levels[0]
    std::size_t fullDetailTriangles = 0;  // of level 0, built or not
    std::vector<float> levelError_mm;     // per pyramid level (all of them): drawn shape error
    std::vector<Mesh> levels;
    // With level 0 built: the parts it is cut into, and the shape error of their reduced
    // copies. Empty when the segment is too short to be worth cutting.
    std::vector<DetailPart> parts;
    float partError_mm = 0.0f;
};

}  // namespace caliper3d::reconstruction

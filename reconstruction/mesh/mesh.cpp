#include "reconstruction/mesh/mesh.h"

#include <algorithm>

namespace caliper3d::reconstruction {

std::size_t Mesh::triangleCount() const {
    std::size_t triangles = 0, run = 0;
    for (std::int32_t index : stripIndices) {
        if (index < 0) {
            if (run >= 3) triangles += run - 2;
            run = 0;
        } else {
            ++run;
        }
    }
    if (run >= 3) triangles += run - 2;
    return triangles;
}

std::size_t Mesh::stripCount() const {
    std::size_t strips = 0;
    for (std::int32_t index : stripIndices) strips += index < 0 ? 1 : 0;
    return strips;
}

void appendClosedStrip(std::vector<std::int32_t>& indices, std::int32_t firstA, std::int32_t firstB,
                       int points) {
    for (int j = 0; j < points; ++j) {
        indices.push_back(firstA + j);
        indices.push_back(firstB + j);
    }
    indices.push_back(firstA);
    indices.push_back(firstB);
    indices.push_back(-1);
}

void appendClosedStrip(std::vector<std::int32_t>& indices, std::int32_t firstA, int pointsA,
                       std::int32_t firstB, int pointsB) {
    if (pointsA == pointsB) {
        appendClosedStrip(indices, firstA, firstB, pointsA);
        return;
    }
    // Both rings start at arm 1 and go the same way round: pair the vertices nearest in
    // angle. Where one ring has no new vertex the pair repeats it, a zero-area triangle.
    const int steps = std::max(pointsA, pointsB);
    for (int k = 0; k <= steps; ++k) {
        const int a = (2 * k * pointsA + steps) / (2 * steps) % pointsA;
        const int b = (2 * k * pointsB + steps) / (2 * steps) % pointsB;
        indices.push_back(firstA + a);
        indices.push_back(firstB + b);
    }
    indices.push_back(-1);
}

}  // namespace caliper3d::reconstruction

#include "reconstruction/mesh/mesh.h"

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

void appendClosedStrip(std::vector<std::int32_t>& indices, std::int32_t firstA,
                       std::int32_t firstB, int points) {
    for (int j = 0; j < points; ++j) {
        indices.push_back(firstA + j);
        indices.push_back(firstB + j);
    }
    indices.push_back(firstA);
    indices.push_back(firstB);
    indices.push_back(-1);
}

}  // namespace caliper3d::reconstruction

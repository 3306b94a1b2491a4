#include "reconstruction/mesh/mesh.h"

#include <gtest/gtest.h>

using namespace caliper3d::reconstruction;

TEST(MeshTest, ClosedStripFollowsReferenceOrderAndCloses) {
    std::vector<std::int32_t> idx;
    appendClosedStrip(idx, 0, 4, 4);
    const std::vector<std::int32_t> expected{0, 4, 1, 5, 2, 6, 3, 7, 0, 4, -1};
    EXPECT_EQ(idx, expected);
}

TEST(MeshTest, NSectionsOfMPointsGiveKnownCounts) {
    const int sections = 7, points = 48;
    Mesh mesh;
    mesh.positions.resize(static_cast<std::size_t>(sections * points));
    for (int s = 1; s < sections; ++s)
        appendClosedStrip(mesh.stripIndices, (s - 1) * points, s * points, points);
    EXPECT_EQ(mesh.stripIndices.size(),
              static_cast<std::size_t>((sections - 1) * (2 * points + 3)));
    EXPECT_EQ(mesh.stripCount(), static_cast<std::size_t>(sections - 1));
    EXPECT_EQ(mesh.triangleCount(), static_cast<std::size_t>((sections - 1) * 2 * points));
    // Every strip starts and ends on the same pair of vertices: the tube is closed.
    std::size_t start = 0;
    for (std::size_t i = 0; i < mesh.stripIndices.size(); ++i) {
        if (mesh.stripIndices[i] != -1) continue;
        EXPECT_EQ(mesh.stripIndices[start], mesh.stripIndices[i - 2]);
        EXPECT_EQ(mesh.stripIndices[start + 1], mesh.stripIndices[i - 1]);
        start = i + 1;
    }
}

#include "scenegraph/segment_node_builder.h"

#include <memory>

#include <Inventor/nodes/SoIndexedTriangleStripSet.h>
#include <Inventor/nodes/SoLOD.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoVertexProperty.h>

#include "coin_fixture.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "scenegraph/node_ref.h"

using namespace caliper3d;

namespace {
class SegmentNodeBuilderTest : public CoinTest {};
}  // namespace

TEST_F(SegmentNodeBuilderTest, StripSetCarriesMeshVerticesNormalsColoursAndIndices) {
    reconstruction::Mesh mesh;
    for (int i = 0; i < 8; ++i) {
        mesh.positions.emplace_back(float(i), 0.0f, 0.0f);
        mesh.normals.emplace_back(0.0f, 1.0f, 0.0f);
        mesh.colours.push_back(0xFF0000FFu);
    }
    reconstruction::appendClosedStrip(mesh.stripIndices, 0, 4, 4);
    auto strips = scenegraph::makeRef(scenegraph::makeStripSet(mesh));
    auto* vp = static_cast<SoVertexProperty*>(strips->vertexProperty.getValue());
    ASSERT_NE(vp, nullptr);
    EXPECT_EQ(vp->vertex.getNum(), 8);
    EXPECT_EQ(vp->normal.getNum(), 8);
    EXPECT_EQ(vp->orderedRGBA.getNum(), 8);
    EXPECT_EQ(vp->vertex[3], SbVec3f(3, 0, 0));
    ASSERT_EQ(strips->coordIndex.getNum(), 11);
    EXPECT_EQ(strips->coordIndex[0], 0);
    EXPECT_EQ(strips->coordIndex[1], 4);
    EXPECT_EQ(strips->coordIndex[10], -1);
}

TEST_F(SegmentNodeBuilderTest, SegmentBecomesLodFinestFirstWithIncreasingRanges) {
    auto table = std::make_shared<const io::SectionTable>(
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("circle", 20.0, 0.1)));
    reconstruction::WellGeometry geometry(table, reconstruction::GeometryOptions{});
    const reconstruction::SegmentMesh segment = geometry.buildSegment(0);
    auto lod = scenegraph::makeRef(scenegraph::makeSegmentLod(segment));
    // Every level, then an empty group for a segment too far to show.
    ASSERT_EQ(lod->getNumChildren(), 5);
    ASSERT_EQ(lod->range.getNum(), 4);
    for (int i = 1; i < 4; ++i) EXPECT_LT(lod->range[i - 1], lod->range[i]) << i;
    EXPECT_EQ(lod->getChild(4)->getTypeId(), SoGroup::getClassTypeId());
    EXPECT_EQ(lod->center.getValue(),
              SbVec3f(segment.centre.x, segment.centre.y, segment.centre.z));
    auto count = [&](int child) {
        // The level's strips, under the separator that lets Coin cache them when there is one.
        SoNode* node = lod->getChild(child);
        if (node->isOfType(SoSeparator::getClassTypeId()))
            node = static_cast<SoSeparator*>(node)->getChild(0);
        auto* s = static_cast<SoIndexedTriangleStripSet*>(node);
        return static_cast<SoVertexProperty*>(s->vertexProperty.getValue())->vertex.getNum();
    };
    EXPECT_EQ(count(0), static_cast<int>(segment.levels[0].positions.size()));
    EXPECT_GT(count(0), count(1));
    EXPECT_GE(count(1), count(2));
    EXPECT_GE(count(2), count(3));
}

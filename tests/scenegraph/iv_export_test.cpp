#include "scenegraph/iv_export.h"
#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/mesh/lod_tree.h"

#include <fstream>
#include <memory>

#include <Inventor/nodes/SoSeparator.h>

#include "coin_fixture.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_geometry.h"
#include "scenegraph/node_ref.h"
#include "scenegraph/well_scene.h"
#include "test_support.h"

using namespace caliper3d;

namespace {
class IvExportTest : public CoinTest {};

std::shared_ptr<const io::SectionTable> exampleTable() {
    return std::make_shared<const io::SectionTable>(
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("example", 60.0, 0.1)));
}
}  // namespace

TEST_F(IvExportTest, RoundTripKeepsVerticesTrianglesAndLods) {
    reconstruction::GeometryOptions options;
    reconstruction::WellGeometry geometry(exampleTable(), options);
    scenegraph::WellScene scene;
    scene.buildAllLevels(geometry);

    // What the geometry says the scene must hold, level by level.
    std::size_t vertices = 0, triangles = 0;
    for (std::size_t s = 0; s < geometry.segmentCount(); ++s)
        for (const auto& level : geometry.buildSegment(s).levels) {
            vertices += level.positions.size();
            triangles += level.triangleCount();
        }
    const scenegraph::SceneCounts before = scenegraph::countScene(scene.root());
    // Every segment's SoLOD, every span's of the tree over them (60 segments: 4 + 1) and the
    // path line's (the line and its coarser copy).
    std::size_t spans = 0;
    for (int d = 1; d <= reconstruction::lodTreeDepth(geometry.segmentCount()); ++d)
        spans += reconstruction::spanCount(d, geometry.segmentCount());
    EXPECT_EQ(spans, 5u);
    EXPECT_EQ(before.lods, geometry.segmentCount() + spans + 1);
    EXPECT_EQ(before.stripSets,
              geometry.segmentCount() * reconstruction::lodPyramid(geometry.options()).size());
    EXPECT_EQ(before.vertices, vertices);
    EXPECT_EQ(before.triangles, triangles);

    for (bool binary : {false, true}) {
        const auto path = test::scratch(binary ? "roundtrip_binary.iv" : "roundtrip_ascii.iv");
        scenegraph::writeIv(scene.root(), path.string(), {binary, false});
        auto back = scenegraph::makeRef(scenegraph::readIv(path.string()));
        const scenegraph::SceneCounts after = scenegraph::countScene(back.get());
        EXPECT_EQ(after.lods, before.lods) << (binary ? "binary" : "ascii");
        EXPECT_EQ(after.stripSets, before.stripSets);
        EXPECT_EQ(after.vertices, before.vertices);
        EXPECT_EQ(after.triangles, before.triangles);
    }
}

TEST_F(IvExportTest, UnwritablePathIsAnErrorNamingTheFile) {
    scenegraph::WellScene scene;
    try {
        scenegraph::writeIv(scene.root(), "/nonexistent-dir/x.iv");
        FAIL() << "expected an error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/x.iv"), std::string::npos);
    }
}

TEST_F(IvExportTest, NonInventorFileIsRejected) {
    const auto path = test::scratch("not_inventor.iv");
    { std::ofstream(path) << "this is not an inventor file\n"; }
    EXPECT_THROW(scenegraph::readIv(path.string()), std::runtime_error);
}

TEST_F(IvExportTest, FullDetailIsStreamedSegmentBySegmentAndReadsBackWhole) {
    reconstruction::GeometryOptions options;
    reconstruction::WellGeometry geometry(exampleTable(), options);
    std::size_t vertices = 0, triangles = 0;
    for (std::size_t s = 0; s < geometry.segmentCount(); ++s)
        for (const auto& level : geometry.buildSegment(s).levels) {
            vertices += level.positions.size();
            triangles += level.triangleCount();
        }
    for (bool binary : {false, true}) {
        const auto path = test::scratch(binary ? "full_binary.iv" : "full_ascii.iv");
        EXPECT_EQ(scenegraph::writeIvFullDetail({&geometry}, path.string(), {binary, false}),
                  geometry.segmentCount());
        auto back = scenegraph::makeRef(scenegraph::readIv(path.string()));
        const scenegraph::SceneCounts after = scenegraph::countScene(back.get());
        EXPECT_EQ(after.lods, geometry.segmentCount() + 1)  // and the path line's
            << (binary ? "binary" : "ascii");
        EXPECT_EQ(after.vertices, vertices) << (binary ? "binary" : "ascii");
        EXPECT_EQ(after.triangles, triangles) << (binary ? "binary" : "ascii");
    }
}

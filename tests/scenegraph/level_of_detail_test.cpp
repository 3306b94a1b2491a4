// Level switching as the camera moves: which levels a WellScene asks for, holds and drops,
// and what SoLOD then draws (SoGetPrimitiveCountAction, as the render verb counts it).
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <Inventor/actions/SoGetPrimitiveCountAction.h>
#include <Inventor/nodes/SoCube.h>
#include <Inventor/nodes/SoLOD.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoSphere.h>

#include <glm/geometric.hpp>

#include "coin_fixture.h"
#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_geometry.h"
#include "scenegraph/node_ref.h"
#include "scenegraph/render_stats.h"
#include "scenegraph/segment_node_builder.h"
#include "scenegraph/well_scene.h"

using namespace caliper3d;

namespace {
class LevelOfDetailTest : public CoinTest {
protected:
    // A 40 m vertical well at 2.5 mm, 1 m segments: 16,001 sections.
    static std::shared_ptr<const reconstruction::WellGeometry> well(double length_m = 40.0) {
        return std::make_shared<const reconstruction::WellGeometry>(
            std::make_shared<const io::SectionTable>(reconstruction::makeSyntheticWell(
                reconstruction::syntheticProfile("example", length_m, 0.0025))),
            reconstruction::GeometryOptions{});
    }

    // Builds and attaches what the scene asks for from `eye`; returns the requests met.
    static std::size_t refine(scenegraph::WellScene& scene,
                              const reconstruction::WellGeometry& geometry, const glm::vec3& eye) {
        const auto wanted = scene.wantedDetail(eye);
        for (const scenegraph::DetailRequest& r : wanted)
            scene.attachFinerLevels(
                reconstruction::buildSegmentLevels(geometry, r.segment, r.level, r.heldFrom));
        return wanted.size();
    }

    // Triangles SoLOD draws from a camera at `eye` looking down (scene -y).
    static std::size_t drawn(scenegraph::WellScene& scene, const glm::vec3& eye) {
        auto root = scenegraph::makeRef(new SoSeparator);
        auto* camera = new SoPerspectiveCamera;
        camera->position.setValue(eye.x, eye.y, eye.z);
        camera->pointAt(SbVec3f(eye.x, eye.y - 10.0f, eye.z), SbVec3f(0, 0, 1));
        root->addChild(camera);
        root->addChild(scene.root());
        return scenegraph::trianglesDrawn(root.get(), 1280, 800);
    }
};
}  // namespace

TEST_F(LevelOfDetailTest, SegmentsNearTheEyeGetFinerLevelsAndFarOnesKeepTheCoarse) {
    const auto geometry = well();
    scenegraph::WellScene scene;
    scene.buildAll(*geometry);
    for (std::size_t s = 0; s < scene.segmentCount(); ++s)
        ASSERT_EQ(scene.heldFrom(s), reconstruction::kFirstCoarseLevel);
    const std::size_t coarse = drawn(scene, {0.0f, -0.5f, 0.0f});

    const glm::vec3 top{0.0f, -1.0f, 0.0f};  // 1 m below the top, on the axis
    ASSERT_GT(refine(scene, *geometry, top), 0u);
    EXPECT_EQ(scene.heldFrom(0), 0);  // the eye's own segments: full detail
    EXPECT_EQ(scene.heldFrom(1), 0);
    EXPECT_EQ(scene.heldFrom(scene.segmentCount() - 1),  // 39 m away: coarse as built
              reconstruction::kFirstCoarseLevel);
    EXPECT_EQ(refine(scene, *geometry, top), 0u);  // nothing more wanted from the same place
    EXPECT_GT(drawn(scene, top), coarse);          // SoLOD draws the finer levels near the eye

    // Moving down the hole asks for the segments there; moving back needs nothing new.
    const glm::vec3 deeper{0.0f, -30.0f, 0.0f};
    ASSERT_GT(refine(scene, *geometry, deeper), 0u);
    EXPECT_EQ(scene.heldFrom(29), 0);
    EXPECT_EQ(refine(scene, *geometry, top), 0u);
}

TEST_F(LevelOfDetailTest, SwitchesFollowTheProjectedSizeNotAFixedDistance) {
    const auto geometry = well(10.0);
    const reconstruction::SegmentMesh segment =
        reconstruction::buildSegmentLevels(*geometry, 5, 0, 99);
    // Twice the pixels over the same field of view, or the same pixels over half the
    // angle: each level is needed twice as far away.
    const auto base = scenegraph::lodSwitchDistances(segment, scenegraph::lodViewFor(800, 0.8f));
    const auto tall = scenegraph::lodSwitchDistances(segment, scenegraph::lodViewFor(1600, 0.8f));
    const auto narrow = scenegraph::lodSwitchDistances(
        segment, scenegraph::lodViewFor(800, 2.0f * std::atan(std::tan(0.4f) / 2.0f)));
    ASSERT_EQ(base.size(), segment.levelError_mm.size());
    for (std::size_t i = 0; i < base.size(); ++i) {
        EXPECT_NEAR(tall[i] - segment.radius, 2.0f * (base[i] - segment.radius), 1e-3f) << i;
        EXPECT_NEAR(narrow[i] - segment.radius, 2.0f * (base[i] - segment.radius), 1e-3f) << i;
        if (i > 0) {
            EXPECT_GE(base[i], base[i - 1]);
        }
    }
    // In haze fog nothing shows past its visibility: no segment is drawn beyond it.
    scenegraph::LodView hazy = scenegraph::lodViewFor(800, 0.8f);
    hazy.visibility_m = 5.0f;
    const auto fogged = scenegraph::lodSwitchDistances(segment, hazy);
    for (std::size_t i = 0; i < fogged.size(); ++i)
        EXPECT_EQ(fogged[i], std::min(base[i], 5.0f + segment.radius)) << i;
    EXPECT_EQ(scenegraph::lodLevelAt(fogged, 5.0f + segment.radius),
              static_cast<int>(fogged.size()));
    EXPECT_EQ(scenegraph::lodLevelAt(base, 0.0f), 0);
    EXPECT_EQ(scenegraph::lodLevelAt(base, base.back() + 1.0f),
              static_cast<int>(base.size()));  // nothing: under the pixel tolerance wide
}

TEST_F(LevelOfDetailTest, FlyingTheWholeWellKeepsTheFineLevelsWithinTheBudget) {
    const auto geometry = well(60.0);
    scenegraph::WellScene scene;
    scene.buildAll(*geometry);
    const std::size_t budget = 400'000;  // triangles of finer-than-coarse levels
    std::size_t most = 0, refined = 0;
    const std::vector<double>& md = geometry->table().depth_m;
    for (float depth = 0.0f; depth <= 60.0f; depth += 0.5f) {
        // On the hole's axis at this measured depth.
        const auto row = static_cast<std::size_t>(
            std::lower_bound(md.begin(), md.end(), static_cast<double>(depth)) - md.begin());
        const glm::vec3 eye(
            reconstruction::toScene(geometry->centre(std::min(row, md.size() - 1))));
        refined += refine(scene, *geometry, eye);
        scene.evictFineLevels(budget);
        most = std::max(most, scene.fineTriangles());
        // The segment the eye is in always holds what it needs.
        const auto segment = static_cast<std::size_t>(std::min(depth, 59.5f));
        EXPECT_EQ(scene.heldFrom(segment), 0) << depth;
    }
    EXPECT_GT(refined, 60u);
    EXPECT_LE(most, budget);
    EXPECT_GT(most, budget / 4);  // the budget was used, not everything dropped at once
}

TEST_F(LevelOfDetailTest, PartsNearTheEyeDrawEverySectionAndFartherPartsTheReducedCopy) {
    const auto geometry = well(10.0);
    const reconstruction::SegmentMesh segment = geometry->buildSegment(1);
    ASSERT_EQ(segment.parts.size(), 4u);
    const scenegraph::LodView view = scenegraph::lodViewFor(800, 0.785398f);
    auto root = scenegraph::makeRef(new SoSeparator);
    auto* camera = new SoPerspectiveCamera;
    root->addChild(camera);
    SoLOD* lod = scenegraph::makeSegmentLod(segment, view);
    root->addChild(lod);
    const std::vector<float> segmentSwitch = scenegraph::lodSwitchDistances(segment, view);
    const reconstruction::Mesh& full = segment.levels.front();
    for (float depth : {1.0f, 1.3f, 1.6f, 1.9f}) {
        // On the axis, looking down: the segment shows level 0, each part by its own distance.
        const glm::vec3 eye(reconstruction::toScene(
            geometry->centre(static_cast<std::size_t>(std::lround(depth / 0.0025)))));
        camera->position.setValue(eye.x, eye.y, eye.z);
        camera->pointAt(SbVec3f(eye.x, eye.y - 10.0f, eye.z), SbVec3f(0, 0, 1));
        ASSERT_LT(glm::length(segment.centre - eye), segmentSwitch[0]);
        std::size_t expected = 0, nearParts = 0;
        for (const reconstruction::DetailPart& part : segment.parts) {
            const float d = glm::length(part.centre - eye);
            if (d < scenegraph::partSwitchDistance(part, segment.partError_mm, view)) {
                ++nearParts;
                for (std::size_t i = part.stripBegin, run = 0; i < part.stripEnd; ++i)
                    if (full.stripIndices[i] < 0) {
                        expected += run - 2;
                        run = 0;
                    } else {
                        ++run;
                    }
            } else {
                expected += part.reduced.triangleCount();
            }
        }
        EXPECT_GE(nearParts, 1u) << depth;      // the part the eye is in
        if (depth < 1.1f || depth > 1.8f) {     // at either end of the segment: the far end
            EXPECT_LE(nearParts, 2u) << depth;  //   shows the reduced copy
        }
        EXPECT_EQ(scenegraph::trianglesDrawn(root.get(), 1280, 800), expected) << depth;
    }
    // A part switches where its reduced copy's shape error projects to the pixel tolerance.
    const reconstruction::DetailPart& part = segment.parts[0];
    EXPECT_NEAR(scenegraph::partSwitchDistance(part, segment.partError_mm, view) - part.radius,
                segment.partError_mm / 1000.0f * view.focal_px / view.pixelTolerance, 1e-5f);
    EXPECT_GT(part.radius, 0.125f);  // half its 0.25 m plus the wall's radius
    EXPECT_LT(part.radius, 0.125f + 0.2f);
    // A new view moves every part's switch.
    const scenegraph::LodView tall = scenegraph::lodViewFor(1600, 0.785398f);
    scenegraph::setPartRanges(lod->getChild(0), segment, tall);
    auto* first = static_cast<SoLOD*>(static_cast<SoGroup*>(lod->getChild(0))->getChild(0));
    EXPECT_FLOAT_EQ(first->range[0],
                    scenegraph::partSwitchDistance(part, segment.partError_mm, tall));
}

TEST_F(LevelOfDetailTest, NodesTraversedCountsOnlyTheChildEachLodPicks) {
    // root: camera, LOD { near: separator of two cubes, far: one sphere } switching at 10 m.
    auto root = scenegraph::makeRef(new SoSeparator);
    auto* camera = new SoPerspectiveCamera;
    root->addChild(camera);
    auto* lod = new SoLOD;
    lod->range.setValue(10.0f);
    auto* near = new SoSeparator;
    near->addChild(new SoCube);
    near->addChild(new SoCube);
    lod->addChild(near);
    lod->addChild(new SoSphere);
    root->addChild(lod);
    camera->position.setValue(0.0f, 0.0f, 5.0f);
    camera->pointAt(SbVec3f(0, 0, 0));
    EXPECT_EQ(scenegraph::nodesTraversed(root.get(), 1280, 800),
              6u);  // root camera lod sep 2 cubes
    camera->position.setValue(0.0f, 0.0f, 50.0f);
    EXPECT_EQ(scenegraph::nodesTraversed(root.get(), 1280, 800), 4u);  // root camera lod sphere
}

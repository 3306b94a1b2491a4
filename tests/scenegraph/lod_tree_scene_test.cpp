// The level-of-detail tree in the scene (WellScene, reconstruction/mesh/lod_tree.h): what a
// camera draws of each segment as it flies from a field's overview into one hole.
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <vector>

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoIndexedTriangleStripSet.h>
#include <Inventor/nodes/SoLOD.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <glm/geometric.hpp>

#include "coin_fixture.h"
#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/mesh/lod_tree.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_geometry.h"
#include "scenegraph/node_ref.h"
#include "scenegraph/render_stats.h"
#include "scenegraph/segment_node_builder.h"
#include "scenegraph/well_scene.h"

using namespace caliper3d;

namespace {

constexpr int kWidth = 1280, kHeight = 800;

// What one camera draws of each segment: its own level, a span's merged mesh over it, or
// nothing because the LOD of the segment or of a span over it chose its empty level.
struct Coverage {
    std::vector<std::set<const SoNode*>> drawnBy;  // per segment: the SoLODs that drew it
    std::vector<int> emptyAt;                      // per segment: the depth that chose nothing
                                                   //   (0: the segment itself; -1: none)
};

class LodTreeSceneTest : public CoinTest {
protected:
    using NodeRefHolder = scenegraph::NodeRef<SoSeparator>;

    // The example well, 300 m at 1 cm: 300 segments, a tree three spans deep.
    static std::shared_ptr<const reconstruction::WellGeometry> well(double exaggeration) {
        reconstruction::GeometryOptions options;
        options.radialExaggeration = exaggeration;
        return std::make_shared<const reconstruction::WellGeometry>(
            std::make_shared<const io::SectionTable>(reconstruction::makeSyntheticWell(
                reconstruction::syntheticProfile("example", 300.0, 0.01))),
            options);
    }

    static NodeRefHolder camera(scenegraph::WellScene& scene, const glm::vec3& eye,
                                const glm::vec3& target) {
        auto root = scenegraph::makeRef(new SoSeparator);
        auto* cam = new SoPerspectiveCamera;
        cam->position.setValue(eye.x, eye.y, eye.z);
        const glm::vec3 up = std::abs(target.x - eye.x) + std::abs(target.z - eye.z) < 1e-3f
                                 ? glm::vec3(0, 0, 1)
                                 : glm::vec3(0, 1, 0);
        cam->pointAt(SbVec3f(target.x, target.y, target.z), SbVec3f(up.x, up.y, up.z));
        root->addChild(cam);
        root->addChild(scene.root());
        return root;
    }

    static Coverage cover(scenegraph::WellScene& scene, SoNode* root) {
        Coverage out;
        out.drawnBy.resize(scene.segmentCount());
        out.emptyAt.assign(scene.segmentCount(), -1);
        struct Walk {
            scenegraph::WellScene* scene;
            Coverage* out;
        } walk{&scene, &out};
        SoCallbackAction action(SbViewportRegion(kWidth, kHeight));
        action.addPreCallback(
            SoNode::getClassTypeId(),
            [](void* data, SoCallbackAction* a, const SoNode* node) {
                auto& w = *static_cast<Walk*>(data);
                const bool strips = node->isOfType(SoIndexedTriangleStripSet::getClassTypeId());
                const bool empty = node->getTypeId() == SoGroup::getClassTypeId() &&
                                   static_cast<const SoGroup*>(node)->getNumChildren() == 0;
                if (!strips && !empty) return SoCallbackAction::CONTINUE;
                const SoPath* path = a->getCurPath();
                // The nearest LOD above it that is a segment's or a span's.
                for (int i = path->getLength() - 2; i >= 0; --i) {
                    const SoNode* above = path->getNode(i);
                    if (const auto s = w.scene->segmentOfLod(above)) {
                        if (empty && i == path->getLength() - 2)
                            w.out->emptyAt[*s] = 0;
                        else if (strips)
                            w.out->drawnBy[*s].insert(above);
                        break;
                    }
                    if (const auto span = w.scene->spanOfLod(above)) {
                        const int child = path->getIndex(i + 1);
                        if (child == 0) continue;  // its children: a deeper LOD decides
                        for (std::size_t s = span->firstSegment; s <= span->lastSegment; ++s) {
                            if (child == 1 && strips) w.out->drawnBy[s].insert(above);
                            if (child == 2) w.out->emptyAt[s] = span->depth;
                        }
                        break;
                    }
                }
                return SoCallbackAction::CONTINUE;
            },
            &walk);
        action.apply(root);
        return out;
    }
};

}  // namespace

TEST_F(LodTreeSceneTest, EverySegmentHangsOnceUnderSpansOfAtMostSixteen) {
    const auto geometry = well(1.0);
    scenegraph::WellScene scene;
    scene.buildAll(*geometry);
    ASSERT_EQ(scene.segmentCount(), 300u);
    EXPECT_EQ(scene.treeDepth(), 3);
    EXPECT_EQ(scene.mergedSpans(), 19u + 2u + 1u);
    SoSearchAction search;
    search.setType(SoLOD::getClassTypeId());
    search.setInterest(SoSearchAction::ALL);
    search.setSearchingAll(TRUE);
    search.apply(scene.root());
    std::map<std::size_t, int> seen;
    std::size_t spans = 0;
    for (int i = 0; i < search.getPaths().getLength(); ++i) {
        const SoPath* path = search.getPaths()[i];
        const SoNode* lod = path->getTail();
        if (const auto s = scene.segmentOfLod(lod)) {
            ++seen[*s];
            // Its span (three above: span SoLOD, its children group) holds it.
            const auto span = scene.spanOfLod(path->getNode(path->getLength() - 3));
            ASSERT_TRUE(span);
            EXPECT_EQ(span->depth, 1);
            EXPECT_LE(span->firstSegment, *s);
            EXPECT_GE(span->lastSegment, *s);
        } else if (scene.spanOfLod(lod)) {
            ++spans;
            const auto* children =
                static_cast<const SoGroup*>(static_cast<const SoLOD*>(lod)->getChild(0));
            EXPECT_LE(children->getNumChildren(), 16);
        }
    }
    EXPECT_EQ(spans, 22u);
    ASSERT_EQ(seen.size(), 300u);
    for (const auto& [segment, count] : seen) EXPECT_EQ(count, 1) << segment;
}

TEST_F(LodTreeSceneTest, FlyingFromTheOverviewIntoTheHoleDrawsEverySegmentOnceWithinTheBudget) {
    // Exaggerated 20 times, as a picture of a long well is drawn: the wall is wide enough to
    // be drawn from every camera of the flight, so no level may be empty on the way.
    const auto geometry = well(20.0);
    scenegraph::WellScene scene;
    scene.buildAll(*geometry);
    scene.setLodView(scenegraph::lodViewFor(kHeight, 0.785398f));
    constexpr std::size_t kBudget = 1'000'000;
    const glm::vec3 middle(0.0f, -150.0f, 0.0f);
    const std::vector<std::pair<glm::vec3, glm::vec3>> flight = {
        {{2000.0f, -150.0f, 0.0f}, middle},  // the overview
        {{1000.0f, -150.0f, 0.0f}, middle},
        {{300.0f, -150.0f, 0.0f}, middle},
        {{80.0f, -150.0f, 0.0f}, middle},
        {{20.0f, -150.0f, 0.0f}, middle},
        {{0.0f, -20.0f, 0.0f}, {0.0f, -60.0f, 0.0f}},  // inside, looking down the hole
        {{0.0f, -70.0f, 0.0f}, {0.0f, -90.0f, 0.0f}},
    };
    std::size_t previous = 0;
    for (std::size_t step = 0; step < flight.size(); ++step) {
        const auto& [eye, target] = flight[step];
        for (const scenegraph::DetailRequest& r : scene.wantedDetail(eye))
            scene.attachFinerLevels(
                reconstruction::buildSegmentLevels(*geometry, r.segment, r.level, r.heldFrom));
        scene.evictFineLevels(kBudget);
        EXPECT_LE(scene.fineTriangles(), kBudget) << step;
        auto root = camera(scene, eye, target);
        const Coverage c = cover(scene, root.get());
        std::size_t byMerged = 0;
        for (std::size_t s = 0; s < scene.segmentCount(); ++s) {
            EXPECT_EQ(c.emptyAt[s], -1) << "step " << step << " segment " << s;
            ASSERT_EQ(c.drawnBy[s].size(), 1u) << "step " << step << " segment " << s;
            byMerged += scene.segmentOfLod(*c.drawnBy[s].begin()) ? 0 : 1;
        }
        const std::size_t triangles = scenegraph::trianglesDrawn(root.get(), kWidth, kHeight);
        if (step == 0) {
            EXPECT_EQ(byMerged, scene.segmentCount());  // the overview: merged meshes only
            EXPECT_LT(triangles, 5'000u);
        }
        if (step + 1 == flight.size()) {
            EXPECT_LT(byMerged, scene.segmentCount());
        }
        EXPECT_LT(triangles, 600'000u) << step;
        if (step > 0 && step < 5) {
            EXPECT_GE(triangles, previous) << step;  // closer: finer
        }
        previous = triangles;
    }
}

TEST_F(LodTreeSceneTest, AWallUnderThePixelToleranceIsLeftToThePathLineAtEveryDepth) {
    // True to size, 8.5 in across: from 3 km the well is far under a pixel wide, and every
    // segment is left out by the span over it, never by a gap in the tree.
    const auto geometry = well(1.0);
    scenegraph::WellScene scene;
    scene.buildAll(*geometry);
    scene.setLodView(scenegraph::lodViewFor(kHeight, 0.785398f));
    auto far = camera(scene, {3000.0f, -150.0f, 0.0f}, {0.0f, -150.0f, 0.0f});
    const Coverage c = cover(scene, far.get());
    for (std::size_t s = 0; s < scene.segmentCount(); ++s) {
        EXPECT_TRUE(c.drawnBy[s].empty()) << s;
        EXPECT_GE(c.emptyAt[s], 1) << s;
    }
    EXPECT_EQ(scenegraph::trianglesDrawn(far.get(), kWidth, kHeight), 0u);
    // Close by, down the hole, the segments near the eye draw themselves.
    auto near = camera(scene, {0.0f, -100.0f, 0.0f}, {0.0f, -120.0f, 0.0f});
    const Coverage n = cover(scene, near.get());
    EXPECT_EQ(n.drawnBy[100].size(), 1u);
    EXPECT_TRUE(scene.segmentOfLod(*n.drawnBy[100].begin()));
}

TEST_F(LodTreeSceneTest, StreamedSegmentsGrowTheTreeAndShowThemselvesUntilTheSpansCome) {
    const auto geometry = well(20.0);
    scenegraph::WellScene scene;
    for (std::size_t s = 0; s < geometry->segmentCount(); ++s) {
        scene.addSegment(reconstruction::buildCoarseSegment(*geometry, s));
        const std::size_t n = s + 1;
        EXPECT_EQ(scene.treeDepth(), n <= 16 ? 1 : n <= 256 ? 2 : 3) << n;
    }
    scene.setLodView(scenegraph::lodViewFor(kHeight, 0.785398f));
    auto overview = camera(scene, {2000.0f, -150.0f, 0.0f}, {0.0f, -150.0f, 0.0f});
    const Coverage before = cover(scene, overview.get());
    for (std::size_t s = 0; s < scene.segmentCount(); ++s) {
        ASSERT_EQ(before.drawnBy[s].size(), 1u) << s;
        EXPECT_TRUE(scene.segmentOfLod(*before.drawnBy[s].begin())) << s;
    }
    const std::size_t segmentsOnly = scenegraph::trianglesDrawn(overview.get(), kWidth, kHeight);
    for (const reconstruction::SpanMesh& span : reconstruction::buildSpanMeshes(*geometry))
        scene.addSpan(span);
    const Coverage after = cover(scene, overview.get());
    for (std::size_t s = 0; s < scene.segmentCount(); ++s) {
        ASSERT_EQ(after.drawnBy[s].size(), 1u) << s;
        EXPECT_FALSE(scene.segmentOfLod(*after.drawnBy[s].begin())) << s;
    }
    EXPECT_LT(scenegraph::trianglesDrawn(overview.get(), kWidth, kHeight) * 10, segmentsOnly);
}

// A scene whose segments are made when a camera first comes near (SegmentNodes::whenNear, as
// a picture holds a field) draws, at every step of the flight from the overview into the
// hole, what the scene that made every segment at once draws: each segment once, by the same
// kind of level (a span's merged mesh or its own), the same triangles. Seen whole it has made
// none; down the hole only those near the eye, each built once.
TEST_F(LodTreeSceneTest, SegmentsMadeWhenNearDrawWhatSegmentsMadeAtOnceDraw) {
    const auto geometry = well(20.0);
    scenegraph::WellScene atOnce;
    atOnce.buildAll(*geometry);
    const reconstruction::CoarsePlan plan =
        reconstruction::planCoarseMeshes(*geometry, reconstruction::kFirstCoarseLevel, {20.0});
    scenegraph::WellScene whenNear;
    std::vector<int> builds(plan.segments.size(), 0);
    scenegraph::WellScene::WaitingSegments waiting;
    waiting.count = plan.segments.size();
    for (const reconstruction::SegmentPlan& s : plan.segments) {
        waiting.fullDetailTriangles += s.fullDetailTriangles;
        waiting.boxes.push_back(reconstruction::plannedSegmentBox(*geometry, s, nullptr));
    }
    waiting.build = [&](std::size_t s) {
        ++builds[s];
        return reconstruction::finishSegmentLevels(*geometry, plan.segments[s], nullptr);
    };
    whenNear.attachAll(*geometry, reconstruction::buildPlannedSpans(*geometry, plan),
                       std::move(waiting));
    ASSERT_EQ(whenNear.segmentCount(), atOnce.segmentCount());
    EXPECT_EQ(whenNear.treeDepth(), atOnce.treeDepth());
    EXPECT_EQ(whenNear.mergedSpans(), atOnce.mergedSpans());
    EXPECT_EQ(whenNear.fullDetailTriangles(), atOnce.fullDetailTriangles());
    EXPECT_EQ(whenNear.segmentNodes(), 0u);
    EXPECT_EQ(atOnce.segmentNodes(), atOnce.segmentCount());
    // Bounded (what frames a picture) as if every segment were there.
    const auto boundsOf = [](scenegraph::WellScene& scene) {
        SoGetBoundingBoxAction bounds{SbViewportRegion(kWidth, kHeight)};
        bounds.apply(scene.root());
        return bounds.getBoundingBox();
    };
    EXPECT_TRUE(boundsOf(whenNear) == boundsOf(atOnce));
    for (scenegraph::WellScene* scene : {&atOnce, &whenNear})
        scene->setLodView(scenegraph::lodViewFor(kHeight, 0.785398f));
    const glm::vec3 middle(0.0f, -150.0f, 0.0f);
    const std::vector<std::pair<glm::vec3, glm::vec3>> flight = {
        {{2000.0f, -150.0f, 0.0f}, middle},  // the overview
        {{300.0f, -150.0f, 0.0f}, middle},
        {{20.0f, -150.0f, 0.0f}, middle},
        {{0.0f, -20.0f, 0.0f}, {0.0f, -60.0f, 0.0f}},  // inside, looking down the hole
        {{0.0f, -70.0f, 0.0f}, {0.0f, -90.0f, 0.0f}},
    };
    for (std::size_t step = 0; step < flight.size(); ++step) {
        SCOPED_TRACE("step " + std::to_string(step));
        const auto& [eye, target] = flight[step];
        std::vector<Coverage> seen;
        std::vector<std::size_t> triangles;
        for (scenegraph::WellScene* scene : {&atOnce, &whenNear}) {
            for (const scenegraph::DetailRequest& r : scene->wantedDetail(eye))
                scene->attachFinerLevels(
                    reconstruction::buildSegmentLevels(*geometry, r.segment, r.level, r.heldFrom));
            auto root = camera(*scene, eye, target);
            seen.push_back(cover(*scene, root.get()));
            triangles.push_back(scenegraph::trianglesDrawn(root.get(), kWidth, kHeight));
        }
        EXPECT_EQ(triangles[1], triangles[0]);
        EXPECT_EQ(whenNear.fineTriangles(), atOnce.fineTriangles());
        for (std::size_t s = 0; s < atOnce.segmentCount(); ++s) {
            EXPECT_EQ(seen[1].emptyAt[s], seen[0].emptyAt[s]) << s;
            ASSERT_EQ(seen[1].drawnBy[s].size(), 1u) << s;
            ASSERT_EQ(seen[0].drawnBy[s].size(), 1u) << s;
            // Drawn by itself (and its own level), or by a span of the same rows.
            const SoNode* a = *seen[0].drawnBy[s].begin();
            const SoNode* b = *seen[1].drawnBy[s].begin();
            EXPECT_EQ(whenNear.segmentOfLod(b), atOnce.segmentOfLod(a)) << s;
            const auto spanA = atOnce.spanOfLod(a);
            const auto spanB = whenNear.spanOfLod(b);
            ASSERT_EQ(spanB.has_value(), spanA.has_value()) << s;
            if (spanA) {
                EXPECT_EQ(spanB->depth, spanA->depth) << s;
                EXPECT_EQ(spanB->firstRow, spanA->firstRow) << s;
            }
        }
        const std::size_t made = whenNear.segmentNodes();
        if (step == 0) {
            EXPECT_EQ(made, 0u);
        }
        if (step + 1 == flight.size()) {
            EXPECT_GT(made, 0u);
            EXPECT_LT(made, whenNear.segmentCount());
        }
        for (std::size_t s = 0; s < builds.size(); ++s) EXPECT_LE(builds[s], 1) << s;
        EXPECT_EQ(static_cast<std::size_t>(std::count(builds.begin(), builds.end(), 1)), made);
    }
}

// A well's path line seen from afar draws its coarser copy (every point of the line within
// kPathTolerance_m of it), from where that distance projects under the pixel tolerance from
// the line's nearest point; nearer, the line itself.
TEST_F(LodTreeSceneTest, APathLineFarAwayDrawsItsCoarserCopyOnlyWhereItsErrorIsUnderAPixel) {
    const auto geometry = well(20.0);
    scenegraph::WellScene scene;
    scene.buildAll(*geometry);
    const scenegraph::LodView view = scenegraph::lodViewFor(kHeight, 0.785398f);
    scene.setLodView(view);
    const std::vector<glm::vec3> line = reconstruction::pathLine(*geometry);
    SoSearchAction search;
    search.setType(SoLOD::getClassTypeId());
    search.setInterest(SoSearchAction::ALL);
    search.apply(scene.root());
    const SoLOD* lod = nullptr;
    for (int i = 0; i < search.getPaths().getLength(); ++i) {
        const SoPath* path = search.getPaths()[i];
        for (int j = 0; j < path->getLength(); ++j)
            if (path->getNode(j)->getName() == SbName("path"))
                lod = static_cast<const SoLOD*>(path->getTail());
    }
    ASSERT_NE(lod, nullptr);
    ASSERT_EQ(lod->getNumChildren(), 2);
    ASSERT_EQ(lod->range.getNum(), 1);
    const auto pointsOf = [](const SoNode* group) {
        const auto* coords =
            static_cast<const SoCoordinate3*>(static_cast<const SoGroup*>(group)->getChild(0));
        std::vector<glm::vec3> out;
        for (int i = 0; i < coords->point.getNum(); ++i)
            out.emplace_back(coords->point[i][0], coords->point[i][1], coords->point[i][2]);
        return out;
    };
    const std::vector<glm::vec3> fine = pointsOf(lod->getChild(0));
    const std::vector<glm::vec3> coarse = pointsOf(lod->getChild(1));
    EXPECT_EQ(fine, line);
    ASSERT_GE(coarse.size(), 2u);
    EXPECT_LE(coarse.size() * 4, fine.size());
    // Every point of the line within the tolerance of the coarser copy.
    float error = 0.0f;
    for (const glm::vec3& p : fine) {
        float best = 1e30f;
        for (std::size_t k = 0; k + 1 < coarse.size(); ++k) {
            const glm::vec3 a = coarse[k], ab = coarse[k + 1] - a;
            const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
            best = std::min(best, glm::length(p - (a + t * ab)));
        }
        error = std::max(error, best);
    }
    EXPECT_LE(error, scenegraph::kPathTolerance_m * 1.0001f);
    // Past the switch every point of the line is far enough for that error to be under the
    // pixel tolerance; nearer than the line's reach to the centre, the line itself is drawn.
    const glm::vec3 centre(lod->center.getValue()[0], lod->center.getValue()[1],
                           lod->center.getValue()[2]);
    float reach = 0.0f;
    for (const glm::vec3& p : fine) reach = std::max(reach, glm::length(p - centre));
    const float nearest = lod->range[0] - reach;
    ASSERT_GT(nearest, 0.0f);
    EXPECT_LE(error * view.focal_px / nearest, view.pixelTolerance * 1.0001f);
    const auto drawnPoints = [&](const glm::vec3& eye) {
        auto root = camera(scene, eye, centre);
        int points = -1;
        SoCallbackAction action(SbViewportRegion(kWidth, kHeight));
        action.addPreCallback(
            SoLineSet::getClassTypeId(),
            [](void* data, SoCallbackAction* a, const SoNode*) {
                const SoPath* path = a->getCurPath();
                for (int i = 0; i < path->getLength(); ++i)
                    if (path->getNode(i)->getName() == SbName("path"))
                        *static_cast<int*>(data) =
                            static_cast<const SoGroup*>(path->getNode(path->getLength() - 2))
                                        ->getNumChildren() == 2
                                ? static_cast<const SoCoordinate3*>(
                                      static_cast<const SoGroup*>(
                                          path->getNode(path->getLength() - 2))
                                          ->getChild(0))
                                      ->point.getNum()
                                : -1;
                return SoCallbackAction::CONTINUE;
            },
            &points);
        action.apply(root.get());
        return points;
    };
    EXPECT_EQ(drawnPoints(centre + glm::vec3(lod->range[0] * 1.01f, 0.0f, 0.0f)),
              static_cast<int>(coarse.size()));
    EXPECT_EQ(drawnPoints(centre + glm::vec3(lod->range[0] * 0.99f, 0.0f, 0.0f)),
              static_cast<int>(fine.size()));
}

// The window's full detail near the camera: a DetailWorker builds, the DetailLoader's timer
// (pumped here on the main thread) attaches, as the camera moves.
#include "scenegraph/detail_loader.h"

#include <chrono>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <Inventor/SoDB.h>
#include <Inventor/sensors/SoSensorManager.h>

#include "coin_fixture.h"
#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_geometry.h"
#include "scenegraph/well_scene.h"

using namespace caliper3d;

namespace {
class DetailLoaderTest : public CoinTest {
protected:
    // Ticks the loader (as its timer would) until it has nothing left to do.
    static bool settle(scenegraph::DetailLoader& loader) {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
        while (std::chrono::steady_clock::now() < deadline) {
            if (loader.tick()) return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
        return false;
    }
    // A 30 m well logged every 2.5 mm (circle profile), its wellhead `east_m` east.
    static std::shared_ptr<const reconstruction::WellGeometry> circleWell(double east_m = 0.0) {
        reconstruction::GeometryOptions options;
        options.wellheadOffset = {0.0, east_m, 0.0};
        return std::make_shared<const reconstruction::WellGeometry>(
            std::make_shared<const io::SectionTable>(reconstruction::makeSyntheticWell(
                reconstruction::syntheticProfile("circle", 30.0, 0.0025))),
            options);
    }
};
}  // namespace

TEST_F(DetailLoaderTest, FinerLevelsFollowTheCameraWithinTheBudget) {
    const auto geometry = circleWell();
    scenegraph::WellScene scene;
    scene.buildAll(*geometry);
    std::optional<scenegraph::DetailView> camera;  // none yet: nothing asked
    const std::size_t budget = 300'000;
    scenegraph::DetailLoader loader([&] { return camera; }, budget);
    loader.addWell(scene, geometry);
    ASSERT_TRUE(settle(loader));
    EXPECT_EQ(scene.fineTriangles(), 0u);

    camera = scenegraph::DetailView{{0.0f, -2.5f, 0.0f}, scenegraph::lodViewFor(800, 0.8f)};
    ASSERT_TRUE(settle(loader));
    EXPECT_EQ(scene.heldFrom(2), 0);  // the eye's segment, at full detail
    EXPECT_EQ(scene.heldFrom(29), reconstruction::kFirstCoarseLevel);
    EXPECT_LE(scene.fineTriangles(), budget);
    // Room for one view's detail, not two: the next view's must push this one out (what the
    // current view needs is never dropped, so the budget is set a little above it).
    ASSERT_GT(scene.fineTriangles(), 0u);
    loader.setBudgetTriangles(scene.fineTriangles() * 11 / 10);

    camera->eye = {0.0f, -25.5f, 0.0f};
    ASSERT_TRUE(settle(loader));
    EXPECT_EQ(scene.heldFrom(25), 0);
    EXPECT_LE(scene.fineTriangles(), loader.budgetTriangles());
    EXPECT_EQ(scene.heldFrom(2), reconstruction::kFirstCoarseLevel);  // dropped: over budget

    loader.removeAll();  // the scene may go now; the worker's results are ignored
    camera->eye = {0.0f, -10.5f, 0.0f};
    EXPECT_TRUE(settle(loader));
    EXPECT_EQ(scene.heldFrom(10), reconstruction::kFirstCoarseLevel);
}

TEST_F(DetailLoaderTest, OneBudgetServesEveryWellOfTheScene) {
    // Two wells 1 km apart; the camera visits two places down the first. With one budget for
    // the scene, room for two views' detail keeps both while the far well holds none (split
    // evenly between the wells, the first view's detail would have gone).
    const auto near = circleWell(0.0), far = circleWell(1000.0);
    scenegraph::WellScene a, b;
    a.buildAll(*near);
    b.buildAll(*far);
    std::optional<scenegraph::DetailView> camera =
        scenegraph::DetailView{{0.0f, -2.5f, 0.0f}, scenegraph::lodViewFor(800, 0.8f)};
    scenegraph::DetailLoader loader([&] { return camera; }, 4'000'000);
    loader.addWell(a, near);
    loader.addWell(b, far);
    ASSERT_TRUE(settle(loader));
    const std::size_t oneView = a.fineTriangles();
    ASSERT_GT(oneView, 0u);
    EXPECT_EQ(b.fineTriangles(), 0u);
    loader.setBudgetTriangles(oneView * 21 / 10);
    camera->eye = {0.0f, -25.5f, 0.0f};
    ASSERT_TRUE(settle(loader));
    EXPECT_EQ(a.heldFrom(25), 0);
    EXPECT_EQ(a.heldFrom(2), 0);  // kept: the scene's budget has room for it
    EXPECT_GT(a.fineTriangles(), loader.budgetTriangles() / 2);
    EXPECT_LE(a.fineTriangles() + b.fineTriangles(), loader.budgetTriangles());
    // Tightened below what is held: the detail idle longest goes, the view's own stays.
    loader.setBudgetTriangles(a.fineTriangles() - oneView / 2);
    camera->eye = {0.0f, -25.4f, 0.0f};
    ASSERT_TRUE(settle(loader));
    EXPECT_EQ(a.heldFrom(25), 0);
    EXPECT_EQ(a.heldFrom(2), reconstruction::kFirstCoarseLevel);
    EXPECT_LE(a.fineTriangles() + b.fineTriangles(), loader.budgetTriangles());
}

TEST_F(DetailLoaderTest, AWellRemovedIsAskedNothingMoreWhileTheOthersKeepTheirDetail) {
    // Two wells side by side; one is forgotten (its scene replaced) while its detail is asked
    // for: the scene goes at once, what the worker built for it is dropped, and the other well
    // still gets its own. (Under AddressSanitizer a scene touched after it went fails here.)
    const auto kept = circleWell(0.0), gone = circleWell(0.5);
    scenegraph::WellScene a;
    auto b = std::make_unique<scenegraph::WellScene>();
    a.buildAll(*kept);
    b->buildAll(*gone);
    std::optional<scenegraph::DetailView> camera =
        scenegraph::DetailView{{0.0f, -2.5f, 0.0f}, scenegraph::lodViewFor(800, 0.8f)};
    scenegraph::DetailLoader loader([&] { return camera; }, 4'000'000);
    loader.addWell(a, kept);
    loader.addWell(*b, gone);
    loader.tick();  // both asked for
    loader.removeWell(*b);
    b.reset();
    loader.removeWell(a);  // and `a` added again: forgotten, then as new
    loader.addWell(a, kept);
    ASSERT_TRUE(settle(loader));
    EXPECT_EQ(a.heldFrom(2), 0);
    EXPECT_GT(a.fineTriangles(), 0u);
    camera->eye = {0.0f, -20.5f, 0.0f};
    ASSERT_TRUE(settle(loader));
    EXPECT_EQ(a.heldFrom(20), 0);
}

TEST_F(DetailLoaderTest, AWellHeldLeanIsReadWholeAgainOnceForItsFinerLevels) {
    // The same well twice: one scene's loader holds the geometry, the other's reads it whole
    // again (a well of a field held lean). Both draw the same finer levels wherever the camera
    // goes; the second reads its well once for all of them.
    const auto geometry = circleWell();
    scenegraph::WellScene held, lean;
    held.buildAll(*geometry);
    lean.buildAll(*geometry);
    std::optional<scenegraph::DetailView> camera;
    scenegraph::DetailLoader heldLoader([&] { return camera; });
    scenegraph::DetailLoader leanLoader([&] { return camera; });
    heldLoader.addWell(held, geometry);
    int reads = 0;
    leanLoader.setWell(lean, [&reads, &geometry] {
        ++reads;  // on the worker; read below only once it has settled
        return geometry;
    });
    ASSERT_TRUE(settle(leanLoader));
    EXPECT_EQ(reads, 0) << "read again with no camera to want its detail";
    for (const float y : {-2.5f, -25.5f, -10.5f}) {
        camera = scenegraph::DetailView{{0.0f, y, 0.0f}, scenegraph::lodViewFor(800, 0.8f)};
        ASSERT_TRUE(settle(heldLoader));
        ASSERT_TRUE(settle(leanLoader));
        ASSERT_GT(held.fineTriangles(), 0u);
        EXPECT_EQ(lean.fineTriangles(), held.fineTriangles()) << y;
        for (std::size_t s = 0; s < held.segmentCount(); ++s)
            ASSERT_EQ(lean.heldFrom(s), held.heldFrom(s)) << y << " m, segment " << s;
    }
    EXPECT_EQ(reads, 1);
    EXPECT_EQ(leanLoader.wholeWellsKept(), 1u);
    leanLoader.removeAll();  // restyled wells read again differently: the whole well goes
    EXPECT_EQ(leanLoader.wholeWellsKept(), 0u);
}

TEST_F(DetailLoaderTest, AWellHeldLeanThatCannotBeReadAgainIsSaidOnceAndKeepsItsCoarseLevels) {
    const auto geometry = circleWell();
    scenegraph::WellScene scene;
    scene.buildAll(*geometry);
    std::optional<scenegraph::DetailView> camera =
        scenegraph::DetailView{{0.0f, -2.5f, 0.0f}, scenegraph::lodViewFor(800, 0.8f)};
    scenegraph::DetailLoader loader([&] { return camera; });
    std::vector<std::string> said;
    loader.setFailureReport([&said](const std::string& message) { said.push_back(message); });
    int reads = 0;
    loader.setWell(scene, [&reads]() -> std::shared_ptr<const reconstruction::WellGeometry> {
        ++reads;
        throw std::runtime_error("well.las: changed since it was loaded");
    });
    ASSERT_TRUE(settle(loader));
    camera->eye = {0.0f, -12.5f, 0.0f};  // asks again elsewhere: the well is not read again
    ASSERT_TRUE(settle(loader));
    ASSERT_EQ(said.size(), 1u);
    EXPECT_EQ(said.front(), "well.las: changed since it was loaded");
    EXPECT_EQ(reads, 1);
    EXPECT_EQ(scene.fineTriangles(), 0u);
    for (std::size_t s = 0; s < scene.segmentCount(); ++s)
        ASSERT_EQ(scene.heldFrom(s), reconstruction::kFirstCoarseLevel) << s;
}

TEST_F(DetailLoaderTest, WellsHeldLeanNearTheCameraAreEachReadOnce) {
    // Three wells held lean a metre apart, the camera among them: the worker builds every job
    // of the well it read last first, so while it keeps two wells read whole it reads each once
    // (nearest first, the camera's requests interleave the wells: it read them again and again).
    std::vector<std::shared_ptr<const reconstruction::WellGeometry>> geometries;
    std::vector<std::unique_ptr<scenegraph::WellScene>> scenes;
    for (int w = 0; w < 3; ++w) {
        geometries.push_back(circleWell(1.0 * w));
        scenes.push_back(std::make_unique<scenegraph::WellScene>());
        scenes.back()->buildAll(*geometries.back());
    }
    std::optional<scenegraph::DetailView> camera =
        scenegraph::DetailView{{1.0f, -12.5f, 0.0f}, scenegraph::lodViewFor(800, 0.8f)};
    scenegraph::DetailLoader loader([&] { return camera; });
    std::vector<int> reads(3, 0);
    for (std::size_t w = 0; w < 3; ++w)
        loader.setWell(*scenes[w], [&reads, &geometries, w] {
            ++reads[w];
            return geometries[w];
        });
    ASSERT_TRUE(settle(loader));
    for (std::size_t w = 0; w < 3; ++w) {
        EXPECT_GT(scenes[w]->fineTriangles(), 0u) << w;
        EXPECT_EQ(reads[w], 1) << w;
    }
}

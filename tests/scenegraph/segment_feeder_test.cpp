#include "scenegraph/segment_feeder.h"

#include <chrono>
#include <memory>
#include <stdexcept>
#include <thread>
#include <variant>

#include <Inventor/SoDB.h>
#include <Inventor/sensors/SoSensorManager.h>

#include "coin_fixture.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "scenegraph/iv_export.h"
#include "scenegraph/well_scene.h"

using namespace caliper3d;

namespace {
class SegmentFeederTest : public CoinTest {
protected:
    // Runs Coin's timer queue on this (the main) thread until the feeder is done.
    static void pump(scenegraph::SegmentFeeder& feeder) {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
        while (!feeder.done() && std::chrono::steady_clock::now() < deadline) {
            SoDB::getSensorManager()->processTimerQueue();
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }
};
reconstruction::GeometryOptions tenMetreSegments() {
    reconstruction::GeometryOptions options;
    options.segmentLength_m = 10.0;
    return options;
}
}  // namespace

TEST_F(SegmentFeederTest, WorkerSegmentsReachTheSceneOnTheMainThread) {
    reconstruction::WellLoadPipeline pipeline(
        [] {
            return reconstruction::makeSyntheticWell(
                reconstruction::syntheticProfile("example", 80.0, 0.1));
        },
        tenMetreSegments());
    scenegraph::WellScene scene;
    std::size_t finishedWith = 0;
    bool started = false;
    scenegraph::SegmentFeeder::Callbacks callbacks;
    callbacks.started = [&](const reconstruction::WellGeometry&) { started = true; };
    callbacks.finished = [&](std::size_t n) { finishedWith = n; };
    scenegraph::SegmentFeeder feeder(pipeline, scene, callbacks, 2);
    pipeline.start();
    pump(feeder);
    ASSERT_TRUE(feeder.done());
    EXPECT_TRUE(started);
    EXPECT_EQ(finishedWith, 8u);  // 80 m in 10 m segments
    EXPECT_EQ(feeder.attached(), 8u);
    // The segments' SoLODs under one span's, which holds its merged mesh once the load ends,
    // and the path line's (the whole well's line and its coarser copy).
    EXPECT_EQ(scenegraph::countScene(scene.root()).lods, 8u + 1u + 1u);
    EXPECT_EQ(scene.treeDepth(), 1);
    EXPECT_EQ(scene.mergedSpans(), 1u);
}

TEST_F(SegmentFeederTest, ReaderFailureIsReportedNotThrown) {
    reconstruction::WellLoadPipeline pipeline(
        []() -> io::SectionTable { throw std::runtime_error("bad.txt:3: expected 10 columns"); },
        reconstruction::GeometryOptions{});
    scenegraph::WellScene scene;
    std::string message;
    scenegraph::SegmentFeeder::Callbacks callbacks;
    callbacks.failed = [&](const std::string& m) { message = m; };
    scenegraph::SegmentFeeder feeder(pipeline, scene, callbacks);
    pipeline.start();
    pump(feeder);
    EXPECT_EQ(message, "bad.txt:3: expected 10 columns");
    EXPECT_EQ(scene.segmentCount(), 0u);
}

TEST_F(SegmentFeederTest, CancelledPipelineStopsEarly) {
    reconstruction::WellLoadPipeline pipeline(
        [] {
            return reconstruction::makeSyntheticWell(
                reconstruction::syntheticProfile("circle", 400.0, 0.01));
        },
        reconstruction::GeometryOptions{});
    pipeline.start();
    pipeline.cancel();
    std::size_t segments = 0;
    for (;;) {
        auto event = pipeline.events().waitPop();
        if (std::holds_alternative<reconstruction::SegmentMesh>(*event)) ++segments;
        if (auto* finished = std::get_if<reconstruction::LoadFinished>(&*event)) {
            EXPECT_EQ(finished->segments, segments);
            break;
        }
        ASSERT_FALSE(std::holds_alternative<reconstruction::LoadFailed>(*event));
    }
    EXPECT_LT(segments, 40u);  // 400 m is 40 segments; cancelled long before the end
}

namespace {
// Waits until `pipeline` has queued `count` events (it has sent them all), at most a minute.
bool waitForQueued(reconstruction::WellLoadPipeline& pipeline, std::size_t count) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (pipeline.events().size() < count && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    return pipeline.events().size() == count;
}
}  // namespace

TEST_F(SegmentFeederTest, ATickTakesBatchesUntilItsBudgetIsSpent) {
    const auto load = [] {
        return reconstruction::makeSyntheticWell(
            reconstruction::syntheticProfile("example", 80.0, 0.1));
    };
    // Every event the load sends, counted on a first pipeline.
    std::size_t events = 0;
    {
        reconstruction::WellLoadPipeline counted(load, tenMetreSegments());
        counted.start();
        for (bool end = false; !end;) {
            const auto event = counted.events().waitPop();
            ++events;
            end = std::holds_alternative<reconstruction::LoadFinished>(*event) ||
                  std::holds_alternative<reconstruction::LoadFailed>(*event);
        }
    }
    ASSERT_GE(events, 11u);  // started, 8 segments, a span, finished

    // No budget: a tick takes one batch, and no more.
    reconstruction::WellLoadPipeline sparing(load, tenMetreSegments());
    sparing.start();
    ASSERT_TRUE(waitForQueued(sparing, events));
    scenegraph::WellScene sparingScene;
    scenegraph::SegmentFeeder sparingFeeder(sparing, sparingScene, {}, 2, 0.0);
    EXPECT_FALSE(sparingFeeder.drainOnce());
    EXPECT_EQ(sparing.events().size(), events - 2);

    // A budget the tick cannot spend: one tick takes every batch, to the load's end.
    reconstruction::WellLoadPipeline generous(load, tenMetreSegments());
    generous.start();
    ASSERT_TRUE(waitForQueued(generous, events));
    scenegraph::WellScene generousScene;
    scenegraph::SegmentFeeder generousFeeder(generous, generousScene, {}, 2, 600000.0);
    EXPECT_TRUE(generousFeeder.drainOnce());
    EXPECT_EQ(generousFeeder.attached(), 8u);
    EXPECT_EQ(generous.events().size(), 0u);
    EXPECT_EQ(generousScene.mergedSpans(), 1u);
}

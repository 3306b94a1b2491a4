// The window's load worker: a cancel stops it, the read of the log included, and opening
// and cancelling loads over and over is clean (run under ThreadSanitizer by make tsan-test).
#include "reconstruction/load/well_load_pipeline.h"

#include <chrono>
#include <random>
#include <string>
#include <thread>
#include <variant>

#include <gtest/gtest.h>

#include "io/column_text_writer.h"
#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "test_support.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {

// A 60 m well logged every 2.5 mm (24,001 rows, about 3.5 MB of text), written once.
const std::string& wellFile() {
    static const std::string path = [] {
        const auto file = test::scratch("pipeline_60m.txt");
        io::writeColumnTextFile(file.string(),
                                makeSyntheticWell(syntheticProfile("example", 60.0, 0.0025)));
        return file.string();
    }();
    return path;
}

// Every event up to the last one (Finished or Failed).
std::vector<LoadEvent> drainAll(WellLoadPipeline& pipeline) {
    std::vector<LoadEvent> events;
    for (;;) {
        auto event = pipeline.events().waitPop();
        events.push_back(std::move(*event));
        if (std::holds_alternative<LoadFinished>(events.back()) ||
            std::holds_alternative<LoadFailed>(events.back()))
            return events;
    }
}

}  // namespace

TEST(WellLoadPipelineTest, LoadsTheWellThenItsCoarseSegments) {
    WellLoadPipeline pipeline(WellSource{wellFile(), {}, {}}, LoadOptions{}, Wellhead{});
    pipeline.start();
    const std::vector<LoadEvent> events = drainAll(pipeline);
    ASSERT_TRUE(std::holds_alternative<LoadStarted>(events.front()));
    const auto& finished = std::get<LoadFinished>(events.back());
    EXPECT_EQ(finished.segments, 60u);  // 1 m segments
    EXPECT_EQ(events.size(), 62u);
    const auto& first = std::get<SegmentMesh>(events[1]);
    EXPECT_EQ(first.firstLevel, kFirstCoarseLevel);  // finer levels come near the camera only
}

TEST(WellLoadPipelineTest, ACancelBeforeTheReadEndsStopsTheReadItself) {
    WellLoadPipeline pipeline(WellSource{wellFile(), {}, {}}, LoadOptions{}, Wellhead{});
    pipeline.cancel();
    pipeline.start();
    const std::vector<LoadEvent> events = drainAll(pipeline);
    // The reader stopped at its first block: no geometry, no segment, nothing failed.
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(std::get<LoadFinished>(events.front()).segments, 0u);
}

TEST(WellLoadPipelineTest, OpeningAndCancellingHundredsOfTimesIsClean) {
    std::mt19937 random(7);
    std::uniform_int_distribution<int> delay_us(0, 4000);
    std::size_t stoppedInTheRead = 0, stoppedLater = 0;
    for (int i = 0; i < 200; ++i) {
        WellLoadPipeline pipeline(WellSource{wellFile(), {}, {}}, LoadOptions{}, Wellhead{});
        pipeline.start();
        std::this_thread::sleep_for(std::chrono::microseconds(delay_us(random)));
        pipeline.cancel();
        const std::vector<LoadEvent> events = drainAll(pipeline);
        ASSERT_FALSE(std::holds_alternative<LoadFailed>(events.back())) << i;
        if (std::holds_alternative<LoadStarted>(events.front()))
            ++stoppedLater;
        else
            ++stoppedInTheRead;
        // The destructor joins the worker here, every time.
    }
    EXPECT_EQ(stoppedInTheRead + stoppedLater, 200u);
    EXPECT_GT(stoppedInTheRead, 0u);
}

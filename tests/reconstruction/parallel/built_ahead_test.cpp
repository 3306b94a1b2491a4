#include "reconstruction/parallel/built_ahead.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

using namespace caliper3d::reconstruction;

namespace {
// Waits until `done` holds, at most a minute.
template <class Done>
bool waitUntil(Done done) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!done() && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return done();
}
}  // namespace

TEST(BuiltAheadTest, ItemsComeInOrderEachBuiltOnceOffTheCallersThread) {
    const std::thread::id caller = std::this_thread::get_id();
    std::atomic<int> offCaller{0};
    std::vector<std::atomic<int>> builds(50);
    BuiltAhead<std::unique_ptr<std::string>> ahead(50, [&](std::size_t i) {
        if (std::this_thread::get_id() != caller) ++offCaller;
        ++builds[i];
        return std::make_unique<std::string>("item " + std::to_string(i));
    });
    for (std::size_t i = 0; i < 50; ++i) EXPECT_EQ(*ahead.take(i), "item " + std::to_string(i));
    for (std::size_t i = 0; i < 50; ++i) EXPECT_EQ(builds[i], 1) << i;
    EXPECT_EQ(offCaller, 50);
}

TEST(BuiltAheadTest, TheWorkersBuildNoFurtherAheadThanAsked) {
    for (const std::size_t workers : {1u, 2u}) {
        SCOPED_TRACE(std::to_string(workers) + " workers");
        std::atomic<std::size_t> built{0};
        BuiltAhead<int> ahead(
            10,
            [&](std::size_t i) {
                ++built;
                return static_cast<int>(i);
            },
            3, workers);
        ASSERT_TRUE(waitUntil([&] { return built == 3; }));
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        EXPECT_EQ(built, 3u);  // items 0-2, and no more until one is taken
        EXPECT_EQ(ahead.take(0), 0);
        ASSERT_TRUE(waitUntil([&] { return built == 4; }));
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        EXPECT_EQ(built, 4u);
    }
}

TEST(BuiltAheadTest, AFailedBuildIsThrownByItsTakeAndTheOthersStillCome) {
    BuiltAhead<int> ahead(3, [](std::size_t i) {
        if (i == 1) throw std::runtime_error("well 1: no rows");
        return static_cast<int>(i) * 10;
    });
    EXPECT_EQ(ahead.take(0), 0);
    try {
        ahead.take(1);
        FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "well 1: no rows");
    }
    EXPECT_EQ(ahead.take(2), 20);
}

TEST(BuiltAheadTest, GoingBeforeEveryItemIsTakenStopsTheWorker) {
    std::atomic<std::size_t> built{0};
    {
        BuiltAhead<int> ahead(1000, [&](std::size_t i) {
            ++built;
            return static_cast<int>(i);
        });
        EXPECT_EQ(ahead.take(0), 0);
    }  // joined here, having built at most two past the one taken
    EXPECT_LE(built, 3u);
}

// Two workers: the first two items are built at the same time (each waits for the other to
// start), never more than two at once, each once, handed over in order.
TEST(BuiltAheadTest, TwoWorkersBuildTwoItemsAtOnceAndHandThemOverInOrder) {
    std::mutex mutex;
    std::condition_variable started;
    int running = 0, most = 0, firstTwo = 0;
    bool overlapped = false;
    std::vector<std::atomic<int>> builds(40);
    {
        BuiltAhead<int> ahead(
            40,
            [&](std::size_t i) {
                {
                    std::unique_lock<std::mutex> lock(mutex);
                    most = std::max(most, ++running);
                    if (i < 2) {
                        ++firstTwo;
                        started.notify_all();
                        // Item 0's worker waits here, so item 1 is the other worker's.
                        overlapped = started.wait_for(lock, std::chrono::seconds(30), [&] {
                            return firstTwo == 2;
                        }) || overlapped;
                    }
                }
                ++builds[i];
                const std::lock_guard<std::mutex> lock(mutex);
                --running;
                return static_cast<int>(i) * 3;
            },
            4, 2);
        for (std::size_t i = 0; i < 40; ++i) EXPECT_EQ(ahead.take(i), static_cast<int>(i) * 3);
    }
    for (std::size_t i = 0; i < 40; ++i) EXPECT_EQ(builds[i], 1) << i;
    EXPECT_TRUE(overlapped);
    EXPECT_EQ(most, 2);
}

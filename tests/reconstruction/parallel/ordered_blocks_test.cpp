#include "reconstruction/parallel/ordered_blocks.h"

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

using namespace caliper3d::reconstruction;

TEST(OrderedBlocksTest, EveryBlockIsWorkedOnceAndFinishedInOrderAfterItsWork) {
    for (int threads : {1, 2, 3, 8}) {
        const std::size_t count = 200;
        std::vector<std::atomic<int>> worked(count);
        std::vector<std::size_t> finished;
        std::atomic<bool> finishedBeforeWork{false};
        forEachBlockInOrder(
            count, threads,
            [&](std::size_t b, std::size_t worker) {
                EXPECT_LT(worker, static_cast<std::size_t>(threads));
                if (b % 7 == 0) std::this_thread::yield();  // let blocks complete out of order
                ++worked[b];
            },
            [&](std::size_t b) {
                if (worked[b] != 1) finishedBeforeWork = true;
                finished.push_back(b);  // finish never runs concurrently with itself
            });
        for (std::size_t b = 0; b < count; ++b) EXPECT_EQ(worked[b], 1) << b;
        ASSERT_EQ(finished.size(), count);
        for (std::size_t b = 0; b < count; ++b) EXPECT_EQ(finished[b], b);
        EXPECT_FALSE(finishedBeforeWork);
    }
}

TEST(OrderedBlocksTest, NoBlocksIsNothingToDo) {
    int calls = 0;
    forEachBlockInOrder(
        0, 4, [&](std::size_t, std::size_t) { ++calls; }, [&](std::size_t) { ++calls; });
    EXPECT_EQ(calls, 0);
}

TEST(OrderedBlocksTest, AWorkersExceptionReachesTheCaller) {
    for (int threads : {1, 2}) {
        EXPECT_THROW(forEachBlockInOrder(
                         100, threads,
                         [](std::size_t b, std::size_t) {
                             if (b == 37) throw std::runtime_error("block 37");
                         },
                         [](std::size_t) {}),
                     std::runtime_error);
    }
}

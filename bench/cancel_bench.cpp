// How soon the window's load worker hands over its first segment, and how long a cancel takes
// to stop a load in progress: opens FILE with
// the load pipeline, cancels after each delay and prints the time from the cancel to the
// worker's last event, and where the load was (reading, or meshing segments).
//   cancel_bench FILE [DELAY_MS...]   (default delays 50 100 200 400 800 1200 ms)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include "reconstruction/load/well_load_pipeline.h"

using namespace caliper3d::reconstruction;
using Clock = std::chrono::steady_clock;

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: cancel_bench FILE [DELAY_MS...]\n");
        return 2;
    }
    std::vector<int> delays;
    for (int i = 2; i < argc; ++i) delays.push_back(std::atoi(argv[i]));
    if (delays.empty()) delays = {50, 100, 200, 400, 800, 1200};
    {
        // How soon the first segment reaches the queue (the window attaches it on its next tick).
        const auto opened = Clock::now();
        WellLoadPipeline pipeline(WellSource{argv[1], {}, {}, {}}, LoadOptions{}, Wellhead{});
        pipeline.start();
        double firstStretch = -1.0, firstSegment = -1.0, whole = -1.0, finished = -1.0;
        auto since = [&] {
            return std::chrono::duration<double, std::milli>(Clock::now() - opened).count();
        };
        for (;;) {
            auto event = pipeline.events().waitPop();
            if (std::holds_alternative<LoadStretch>(*event) && firstStretch < 0)
                firstStretch = since();
            if (std::holds_alternative<SegmentMesh>(*event) && firstSegment < 0)
                firstSegment = since();
            if (std::holds_alternative<LoadStarted>(*event)) whole = since();
            if (std::holds_alternative<LoadFinished>(*event) ||
                std::holds_alternative<LoadFailed>(*event)) {
                finished = since();
                break;
            }
        }
        std::printf(
            "| open to first stretch | to first segment | to whole geometry | to last segment |\n"
            "|---|---|---|---|\n| %.0f ms | %.0f ms | %.0f ms | %.0f ms |\n\n",
            firstStretch, firstSegment, whole, finished);
    }
    std::printf("| cancel after (ms) | stopped while | cancel to stop (ms) |\n|---|---|---|\n");
    for (int delay : delays) {
        WellLoadPipeline pipeline(WellSource{argv[1], {}, {}, {}}, LoadOptions{}, Wellhead{});
        pipeline.start();
        std::this_thread::sleep_for(std::chrono::milliseconds(delay));
        const auto cancelled = Clock::now();
        pipeline.cancel();
        bool started = false;
        for (;;) {
            auto event = pipeline.events().waitPop();
            started = started || std::holds_alternative<LoadStarted>(*event);
            if (std::holds_alternative<LoadFinished>(*event) ||
                std::holds_alternative<LoadFailed>(*event))
                break;
        }
        const double ms =
            std::chrono::duration<double, std::milli>(Clock::now() - cancelled).count();
        std::printf("| %d | %s | %.1f |\n", delay, started ? "meshing" : "reading or building", ms);
    }
    return 0;
}

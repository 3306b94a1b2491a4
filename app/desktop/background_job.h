#pragma once

#include <functional>
#include <memory>
#include <thread>

class QObject;

namespace caliper3d::app {

// Runs `work` on a worker thread and runs what it returns on the main thread, through
// `context`'s event queue: the worker makes plain data (no Qt or Coin call but the queued
// hand-over), the main thread puts it into the model and the scene. The destructor waits for
// the worker; what `work` returned is not run after it. The load hand-off's rule
// (docs/threading.md) for the jobs that follow a load: the analysis, the runs' depth match,
// the comparison a wall is coloured by.
class BackgroundJob {
public:
    using Work = std::function<std::function<void()>()>;

    BackgroundJob(QObject* context, Work work);
    ~BackgroundJob();
    BackgroundJob(const BackgroundJob&) = delete;
    BackgroundJob& operator=(const BackgroundJob&) = delete;

private:
    std::shared_ptr<bool> m_alive;  // main thread only: false once destroyed
    std::thread m_worker;
};

}  // namespace caliper3d::app

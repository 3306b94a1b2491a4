#include "app/desktop/background_job.h"

#include <memory>
#include <mutex>
#include <utility>

#include <QMetaObject>
#include <QObject>

namespace caliper3d::app {

namespace {

// What the worker hands over, under a mutex of its own: Qt's event queue orders the queued
// call after the worker's work, but through a lock ThreadSanitizer cannot see (Qt is not built
// with it), so the main thread's reads of what the work made (an analysis, a well's form) read
// as races wherever they are not made from inside Qt. The mutex makes the order plain to it.
struct HandOver {
    std::mutex mutex;
    std::function<void()> then;
};

}  // namespace

BackgroundJob::BackgroundJob(QObject* context, Work work) : m_alive(std::make_shared<bool>(true)) {
    m_worker = std::thread([context, work = std::move(work), alive = m_alive]() {
        auto handed = std::make_shared<HandOver>();
        {
            std::function<void()> then = work();
            const std::lock_guard<std::mutex> lock(handed->mutex);
            handed->then = std::move(then);
        }
        // `alive` is read on the main thread only, inside the queued call.
        QMetaObject::invokeMethod(
            context,
            [handed, alive]() {
                std::function<void()> then;
                {
                    const std::lock_guard<std::mutex> lock(handed->mutex);
                    then = std::move(handed->then);
                }
                if (*alive && then) then();
            },
            Qt::QueuedConnection);
    });
}

BackgroundJob::~BackgroundJob() {
    *m_alive = false;
    if (m_worker.joinable()) m_worker.join();
}

}  // namespace caliper3d::app

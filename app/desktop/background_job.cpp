#include "app/desktop/background_job.h"

#include <utility>

#include <QMetaObject>
#include <QObject>

namespace caliper3d::app {

BackgroundJob::BackgroundJob(QObject* context, Work work) : m_alive(std::make_shared<bool>(true)) {
    m_worker = std::thread([context, work = std::move(work), alive = m_alive]() {
        std::function<void()> then = work();
        // `alive` is read on the main thread only, inside the queued call.
        QMetaObject::invokeMethod(
            context,
            [then = std::move(then), alive]() {
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

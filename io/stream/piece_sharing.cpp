#include "io/stream/piece_sharing.h"

namespace caliper3d::io {

PieceSharing::PieceSharing(bool withWorker) {
    if (withWorker) m_worker = std::thread([this] { work(); });
}

PieceSharing::~PieceSharing() {
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_stop = true;
    }
    m_wake.notify_all();
    if (m_worker.joinable()) m_worker.join();
}

void PieceSharing::run(std::size_t count, const std::function<void(std::size_t)>& task) {
    if (!m_worker.joinable()) {
        for (std::size_t i = 0; i < count; ++i) task(i);
        return;
    }
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_task = &task;
        m_count = count;
        m_next = 0;
        m_done = 0;
        ++m_generation;
    }
    m_wake.notify_one();
    std::unique_lock<std::mutex> lock(m_mutex);
    while (m_next < m_count) {
        const std::size_t i = m_next++;
        lock.unlock();
        task(i);
        lock.lock();
        ++m_done;
    }
    m_finished.wait(lock, [&] { return m_done == m_count; });
    m_task = nullptr;
}

void PieceSharing::work() {
    std::unique_lock<std::mutex> lock(m_mutex);
    std::uint64_t seen = 0;
    for (;;) {
        m_wake.wait(lock, [&] { return m_stop || m_generation != seen; });
        if (m_stop) return;
        seen = m_generation;
        while (m_task && m_next < m_count) {
            const std::size_t i = m_next++;
            const std::function<void(std::size_t)>& task = *m_task;
            lock.unlock();
            task(i);
            lock.lock();
            if (++m_done == m_count) m_finished.notify_one();
        }
    }
}

}  // namespace caliper3d::io

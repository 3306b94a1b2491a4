#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

namespace caliper3d::reconstruction {

// The one hand-off type between workers and the main thread: a mutex-guarded
// FIFO of plain data. Workers push; the main thread drains it from a Coin
// sensor (Debian's Coin has no thread-safe sensor queue, so workers never
// touch Coin; see docs/threading.md).
template <typename T>
class HandOffQueue {
public:
    void push(T item) {
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            m_items.push_back(std::move(item));
        }
        m_ready.notify_one();
    }

    // Takes up to `most` items without waiting.
    std::vector<T> drain(std::size_t most) {
        std::lock_guard<std::mutex> lock(m_mutex);
        std::vector<T> out;
        while (!m_items.empty() && out.size() < most) {
            out.push_back(std::move(m_items.front()));
            m_items.pop_front();
        }
        return out;
    }

    std::optional<T> waitPop() {
        std::unique_lock<std::mutex> lock(m_mutex);
        m_ready.wait(lock, [&] { return !m_items.empty(); });
        T item = std::move(m_items.front());
        m_items.pop_front();
        return item;
    }

    std::size_t size() const {
        std::lock_guard<std::mutex> lock(m_mutex);
        return m_items.size();
    }

private:
    mutable std::mutex m_mutex;
    std::condition_variable m_ready;
    std::deque<T> m_items;
};

}  // namespace caliper3d::reconstruction

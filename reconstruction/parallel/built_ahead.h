#pragma once

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

namespace caliper3d::reconstruction {

// Items [0, count) built in order on one worker thread, up to `ahead` items before the one the
// caller takes next; the caller takes them in order. What a well's coarse meshes are to the
// main thread, which alone makes Coin nodes of them (docs/threading.md): the worker builds the
// next well's meshes while the main thread makes the last one's nodes. An exception from
// `build` is rethrown by take() for that item. The worker stops, and is joined, when this goes
// (items not taken are built no further).
template <class T>
class BuiltAhead {
public:
    BuiltAhead(std::size_t count, std::function<T(std::size_t)> build, std::size_t ahead = 2)
        : m_slots(count),
          m_ahead(ahead > 0 ? ahead : 1),
          m_worker([this, build = std::move(build)] { run(build); }) {}
    ~BuiltAhead() {
        {
            const std::lock_guard<std::mutex> lock(m_mutex);
            m_stop = true;
        }
        m_changed.notify_all();
        m_worker.join();
    }
    BuiltAhead(const BuiltAhead&) = delete;
    BuiltAhead& operator=(const BuiltAhead&) = delete;

    // Item `i`, once built; items are taken in order, each once.
    T take(std::size_t i) {
        std::unique_lock<std::mutex> lock(m_mutex);
        m_changed.wait(lock, [&] { return m_built > i; });
        Slot slot = std::move(m_slots[i]);
        m_taken = i + 1;
        lock.unlock();
        m_changed.notify_all();
        if (slot.error) std::rethrow_exception(slot.error);
        return std::move(*slot.value);
    }

private:
    struct Slot {
        std::optional<T> value;
        std::exception_ptr error;
    };

    void run(const std::function<T(std::size_t)>& build) {
        for (std::size_t i = 0; i < m_slots.size(); ++i) {
            {
                std::unique_lock<std::mutex> lock(m_mutex);
                m_changed.wait(lock, [&] { return m_stop || i < m_taken + m_ahead; });
                if (m_stop) return;
            }
            Slot slot;
            try {
                slot.value.emplace(build(i));
            } catch (...) {
                slot.error = std::current_exception();
            }
            {
                const std::lock_guard<std::mutex> lock(m_mutex);
                m_slots[i] = std::move(slot);
                m_built = i + 1;
            }
            m_changed.notify_all();
        }
    }

    std::mutex m_mutex;  // guards everything below but the worker
    std::condition_variable m_changed;
    std::vector<Slot> m_slots;
    std::size_t m_ahead;
    std::size_t m_built = 0;  // items [0, m_built) are in their slots
    std::size_t m_taken = 0;  // items [0, m_taken) have been taken
    bool m_stop = false;
    std::thread m_worker;  // last: started once the rest is in place
};

}  // namespace caliper3d::reconstruction

#pragma once

#include <algorithm>
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

// Items [0, count) built on `workers` worker threads (one by default), each worker taking the
// next item not yet started, up to `ahead` items before the one the caller takes next; the
// caller takes them in order. What a well's coarse meshes are to the main thread, which alone
// makes Coin nodes of them (docs/threading.md): a worker builds the next well's meshes while
// the main thread makes the last one's nodes (a field held lean builds two wells at a time).
// An exception from `build` is rethrown by take() for that item. The workers stop, and are
// joined, when this goes (items not taken are built no further; one being built is finished).
template <class T>
class BuiltAhead {
public:
    BuiltAhead(std::size_t count, std::function<T(std::size_t)> build, std::size_t ahead = 2,
               std::size_t workers = 1)
        : m_slots(count), m_ahead(ahead > 0 ? ahead : 1), m_build(std::move(build)) {
        const std::size_t threads = std::max<std::size_t>(1, std::min(workers, m_ahead));
        m_workers.reserve(threads);
        for (std::size_t t = 0; t < threads; ++t) m_workers.emplace_back([this] { run(); });
    }
    ~BuiltAhead() {
        {
            const std::lock_guard<std::mutex> lock(m_mutex);
            m_stop = true;
        }
        m_changed.notify_all();
        for (std::thread& worker : m_workers) worker.join();
    }
    BuiltAhead(const BuiltAhead&) = delete;
    BuiltAhead& operator=(const BuiltAhead&) = delete;

    // Item `i`, once built; items are taken in order, each once.
    T take(std::size_t i) {
        std::unique_lock<std::mutex> lock(m_mutex);
        m_changed.wait(lock, [&] { return m_slots[i].built; });
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
        bool built = false;
    };

    void run() {
        for (;;) {
            std::size_t i = 0;
            {
                std::unique_lock<std::mutex> lock(m_mutex);
                m_changed.wait(lock, [&] {
                    return m_stop || m_next >= m_slots.size() || m_next < m_taken + m_ahead;
                });
                if (m_stop || m_next >= m_slots.size()) return;
                i = m_next++;
            }
            Slot slot;
            try {
                slot.value.emplace(m_build(i));
            } catch (...) {
                slot.error = std::current_exception();
            }
            slot.built = true;
            {
                const std::lock_guard<std::mutex> lock(m_mutex);
                m_slots[i] = std::move(slot);
            }
            m_changed.notify_all();
        }
    }

    std::mutex m_mutex;  // guards everything below but the build and the workers
    std::condition_variable m_changed;
    std::vector<Slot> m_slots;
    std::size_t m_ahead;
    std::size_t m_next = 0;   // the next item a worker starts
    std::size_t m_taken = 0;  // items [0, m_taken) have been taken
    bool m_stop = false;
    std::function<T(std::size_t)> m_build;  // called on the workers, at once on several
    std::vector<std::thread> m_workers;     // last: started once the rest is in place
};

}  // namespace caliper3d::reconstruction

#pragma once

#include <cstddef>
#include <memory>
#include <type_traits>
#include <utility>

namespace caliper3d::reconstruction {

// A fixed-size array whose elements are constructed by whoever fills it,
// each exactly once before it is read (workers in parallel, say), instead of
// being value-initialised first as std::vector's are: for an array of a
// hundred megabytes filled by workers, that first pass, on one thread, is a
// large sequential cost. For trivially copyable types only.
template <class T>
class FillArray {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

public:
    FillArray() = default;
    explicit FillArray(std::size_t size)
        : m_data(size > 0 ? std::allocator<T>().allocate(size) : nullptr), m_size(size) {}
    FillArray(const FillArray& other) : FillArray(other.m_size) {
        if (m_size > 0) std::uninitialized_copy(other.m_data, other.m_data + m_size, m_data);
    }
    FillArray(FillArray&& other) noexcept
        : m_data(std::exchange(other.m_data, nullptr)), m_size(std::exchange(other.m_size, 0)) {}
    FillArray& operator=(FillArray other) noexcept {
        std::swap(m_data, other.m_data);
        std::swap(m_size, other.m_size);
        return *this;
    }
    ~FillArray() {
        if (m_data) std::allocator<T>().deallocate(m_data, m_size);
    }

    // Constructs element i.
    void set(std::size_t i, const T& value) { ::new (static_cast<void*>(m_data + i)) T(value); }

    // Element access, once constructed.
    const T& operator[](std::size_t i) const { return m_data[i]; }
    T& operator[](std::size_t i) { return m_data[i]; }
    T* data() { return m_data; }
    const T* data() const { return m_data; }
    std::size_t size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    const T* begin() const { return m_data; }
    const T* end() const { return m_data + m_size; }
    T* begin() { return m_data; }
    T* end() { return m_data + m_size; }
    const T& front() const { return m_data[0]; }
    const T& back() const { return m_data[m_size - 1]; }

private:
    T* m_data = nullptr;
    std::size_t m_size = 0;
};

}  // namespace caliper3d::reconstruction

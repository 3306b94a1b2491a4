#pragma once

#include <cstddef>
#include <cstring>
#include <vector>

namespace caliper3d::app {

// One value a row, read where it lies: a vector of values, or one double or float field of an
// array of records (the analysis's per-section store, the well's path), so a dock draws
// a 1.6-million-row curve without a copy of it (docs/architecture.md, "Memory per well"). Whatever
// it reads must outlive it.
class RowCurve {
public:
    RowCurve() = default;
    // A vector is a curve: implicit, so a caller passes one as it is.
    RowCurve(const std::vector<double>& values)  // NOLINT(google-explicit-constructor)
        : RowCurve(values.data(), sizeof(double), values.size()) {}
    // `size` values, the first at `first`, each the next `strideBytes` bytes further on.
    RowCurve(const double* first, std::size_t strideBytes, std::size_t size)
        : RowCurve(first, strideBytes, size, false) {}
    // The same, of single-precision values.
    RowCurve(const float* first, std::size_t strideBytes, std::size_t size)
        : RowCurve(first, strideBytes, size, true) {}
    // The field `member` of `size` records from `records` on.
    template <class Record, class Value>
    static RowCurve field(const Record* records, Value Record::*member, std::size_t size) {
        return size == 0 ? RowCurve() : RowCurve(&(records->*member), sizeof(Record), size);
    }

    std::size_t size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    double operator[](std::size_t row) const {
        if (m_single) {
            float v;
            std::memcpy(&v, m_first + row * m_stride, sizeof v);
            return v;
        }
        double v;
        std::memcpy(&v, m_first + row * m_stride, sizeof v);
        return v;
    }
    double front() const { return (*this)[0]; }
    double back() const { return (*this)[m_size - 1]; }

private:
    RowCurve(const void* first, std::size_t strideBytes, std::size_t size, bool single)
        : m_first(static_cast<const unsigned char*>(first)),
          m_stride(strideBytes),
          m_size(first ? size : 0),
          m_single(single) {}

    const unsigned char* m_first = nullptr;
    std::size_t m_stride = sizeof(double);
    std::size_t m_size = 0;
    bool m_single = false;
};

}  // namespace caliper3d::app

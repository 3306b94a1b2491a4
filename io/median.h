#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace caliper3d::io {

// The median of `values` as every figure of caliper3d takes it: the upper middle element
// (values[n / 2] once sorted, no average of the two middle ones, so the median is always a
// value that was measured). Reorders `values`; NaN for an empty vector.
inline double medianInPlace(std::vector<double>& values) {
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), mid, values.end());
    return *mid;
}

}  // namespace caliper3d::io

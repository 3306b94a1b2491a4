#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "io/section_table.h"

namespace caliper3d::io {

// The middle value of `values` (of an even count, the upper of the two middle
// ones: always a value that occurs), NaN when there is none. Linear time.
inline double upperMedian(std::vector<double> values) {
    if (values.empty()) return kNaN;
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

}  // namespace caliper3d::io

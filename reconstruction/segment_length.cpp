#include "reconstruction/segment_length.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace caliper3d::reconstruction {

double autoSegmentLength(const std::vector<double>& depth_m) {
    const std::size_t rows = std::min(depth_m.size(), kSegmentStepRows);
    if (rows < 2) return 1.0;
    std::vector<double> steps;
    steps.reserve(rows - 1);
    for (std::size_t i = 1; i < rows; ++i) steps.push_back(std::abs(depth_m[i] - depth_m[i - 1]));
    const auto middle = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
    std::nth_element(steps.begin(), middle, steps.end());
    const double span = *middle * kRowsPerSegment;
    return std::isfinite(span) && span > 1.0 ? std::ceil(span - 1e-9) : 1.0;
}

}  // namespace caliper3d::reconstruction

#include "reconstruction/well_interval.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace caliper3d::reconstruction {

std::shared_ptr<const WellGeometry> intervalGeometry(const WellGeometry& whole, double top_m,
                                                     double bottom_m, GeometryOptions options) {
    const std::vector<double>& depth = whole.table().depth_m;
    const auto first = static_cast<std::size_t>(
        std::lower_bound(depth.begin(), depth.end(), top_m) - depth.begin());
    const auto last = static_cast<std::size_t>(
        std::upper_bound(depth.begin(), depth.end(), bottom_m) - depth.begin());
    if (last < first + 2) {
        char range[96];
        std::snprintf(range, sizeof range, "%.3f to %.3f m", top_m, bottom_m);
        throw std::invalid_argument(whole.table().source + ": fewer than two sections lie in " +
                                    range);
    }
    auto table = std::make_shared<const io::SectionTable>(whole.table().rows(first, last));
    options.continueFrom.reset();
    if (options.survey.empty() && first > 0) options.continueFrom = whole.path()[first];
    options.cancel = nullptr;
    options.colouring.reset();  // one value per row of the whole: colour the interval anew
    return std::make_shared<const WellGeometry>(std::move(table), options);
}

}  // namespace caliper3d::reconstruction

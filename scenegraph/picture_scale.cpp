#include "scenegraph/picture_scale.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

#include "reconstruction/well_path.h"

namespace caliper3d::scenegraph {

namespace {
constexpr std::size_t kSampledRows = 4096;

// Rows [first, last) of `depth` within [top, bottom].
std::pair<std::size_t, std::size_t> rowsIn(const std::vector<double>& depth, double top,
                                           double bottom) {
    const auto first =
        static_cast<std::size_t>(std::lower_bound(depth.begin(), depth.end(), top) - depth.begin());
    const auto last = static_cast<std::size_t>(
        std::upper_bound(depth.begin(), depth.end(), bottom) - depth.begin());
    return {first, std::max(first, last)};
}
}  // namespace

double tickSpacing_m(double visibleLength_m) {
    if (!(visibleLength_m > 0.0) || !std::isfinite(visibleLength_m)) return 1.0;
    const double least = visibleLength_m / kMaxDepthTicks;
    double decade = std::pow(10.0, std::floor(std::log10(least)));
    for (;;) {
        for (double m : {1.0, 2.0, 5.0})
            if (m * decade >= least * (1.0 - 1e-12)) return m * decade;
        decade *= 10.0;
    }
}

double roundUpToSeries(double value) {
    if (!(value > 0.0) || !std::isfinite(value)) return 1.0;
    double decade = std::pow(10.0, std::floor(std::log10(value)));
    for (;;) {
        for (double m : {1.0, 2.0, 3.0, 5.0})
            if (m * decade >= value * (1.0 - 1e-12)) return m * decade;
        decade *= 10.0;
    }
}

double autoExaggeration(double extent_m, double typicalRadius_m, int pictureHeight_px) {
    if (!(extent_m > 0.0) || !(typicalRadius_m > 0.0) || pictureHeight_px <= 0) return 1.0;
    const double fraction =
        std::max(kMinDrawnDiameter, kMinDrawnDiameter_px / static_cast<double>(pictureHeight_px));
    const double wanted = fraction * extent_m / (2.0 * typicalRadius_m);
    if (wanted <= 1.0) return 1.0;
    return std::min(roundUpToSeries(wanted), kMaxExaggeration);
}

double chooseExaggeration(
    const std::vector<std::shared_ptr<const reconstruction::WellGeometry>>& wells, double top_m,
    double bottom_m, int pictureHeight_px) {
    Bounds bounds;
    double radius = std::numeric_limits<double>::infinity();
    for (const auto& well : wells) {
        const std::vector<double>& depth = well->table().depth_m;
        if (depth.empty()) continue;
        const double top = std::max(top_m, depth.front());  // the log, not the path above it
        addPathBounds(*well, top, bottom_m, bounds);
        const double r = typicalRadius_m(*well, top, bottom_m);
        if (std::isfinite(r)) radius = std::min(radius, r);  // the thinnest hole reads too
    }
    return autoExaggeration(bounds.diagonal(), radius, pictureHeight_px);
}

void Bounds::add(const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
}

double Bounds::diagonal() const {
    return empty() ? 0.0 : glm::length(hi - lo);
}

void addPathBounds(const reconstruction::WellGeometry& geometry, double top_m, double bottom_m,
                   Bounds& bounds) {
    const std::vector<double>& depth = geometry.table().depth_m;
    if (depth.empty()) return;
    if (top_m < depth.front()) {
        // The path from the wellhead down to the first row (an arc: its ends and middle bound it
        // closely enough for a scale).
        const double first = depth.front();
        for (double md : {std::max(top_m, 0.0), 0.5 * (std::max(top_m, 0.0) + first)})
            bounds.add(reconstruction::pathAt(geometry, md).position);
    }
    const auto [first, last] = rowsIn(depth, top_m, bottom_m);
    if (first == last) return;
    const std::size_t stride = std::max<std::size_t>(1, (last - first) / kSampledRows);
    for (std::size_t row = first; row < last; row += stride) bounds.add(geometry.centre(row));
    bounds.add(geometry.centre(last - 1));
}

double typicalRadius_m(const reconstruction::WellGeometry& geometry, double top_m,
                       double bottom_m) {
    const io::SectionTable& table = geometry.table();
    const auto [first, last] = rowsIn(table.depth_m, top_m, bottom_m);
    const std::size_t stride = std::max<std::size_t>(1, (last - first) / kSampledRows);
    std::vector<double> radii;
    for (std::size_t row = first; row < last; row += stride) {
        if (!geometry.measured(row)) continue;
        const double* r = table.radii(row);
        for (int arm = 0; arm < table.armCount; ++arm)
            if (std::isfinite(r[arm]) && r[arm] > 0.0) radii.push_back(r[arm]);
    }
    if (radii.empty()) return std::nan("");
    const auto middle = radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 2);
    std::nth_element(radii.begin(), middle, radii.end());
    return *middle / 1000.0;
}

}  // namespace caliper3d::scenegraph

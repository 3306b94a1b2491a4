#include "reconstruction/analysis/unrolled_image.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "reconstruction/section/periodic_spline.h"

namespace caliper3d::reconstruction {

namespace {

constexpr float kNoData = std::numeric_limits<float>::quiet_NaN();

// The table row nearest `md_m`; none beyond the log's ends by more than `margin_m`.
std::optional<std::size_t> nearestRow(const std::vector<double>& depth_m, double md_m,
                                      double margin_m) {
    if (depth_m.empty() || md_m < depth_m.front() - margin_m || md_m > depth_m.back() + margin_m)
        return std::nullopt;
    const auto after = std::lower_bound(depth_m.begin(), depth_m.end(), md_m);
    if (after == depth_m.begin()) return 0;
    if (after == depth_m.end()) return depth_m.size() - 1;
    const auto i = static_cast<std::size_t>(after - depth_m.begin());
    return md_m - depth_m[i - 1] <= depth_m[i] - md_m ? i - 1 : i;
}

// One row of the image from table row `row`.
void fillRow(const WellGeometry& g, std::size_t row, double gauge_mm,
             const UnrolledImageRequest& request, float* out) {
    const auto columns = static_cast<std::size_t>(request.columns);
    if (!g.measured(row) || !std::isfinite(gauge_mm) ||
        !referenceKnown(g, row, request.reference)) {
        std::fill(out, out + columns, kNoData);
        return;
    }
    std::vector<double> knots(static_cast<std::size_t>(g.knotCount()));
    g.sectionKnots(row, knots.data());
    const PeriodicSpline spline(knots);
    const double arm1 = arm1Angle_deg(g.frame(row), request.reference);
    // The spline's parameter runs over the knots, one per 360 / knots degrees from arm 1.
    const double perDegree = g.knotCount() / 360.0;
    for (std::size_t c = 0; c < columns; ++c) {
        const double angle = (static_cast<double>(c) + 0.5) * 360.0 / request.columns;
        out[c] = static_cast<float>(spline((angle - arm1) * perDegree) - gauge_mm);
    }
}

}  // namespace

UnrolledImage unrolledImage(const WellGeometry& g, const UnrolledImageRequest& request,
                            const std::function<double(std::size_t)>& gaugeRadius_mm) {
    UnrolledImage image;
    image.top_m = request.top_m;
    image.bottom_m = request.bottom_m;
    image.rows = std::max(request.rows, 0);
    image.columns = std::max(request.columns, 0);
    image.reference = request.reference;
    const auto columns = static_cast<std::size_t>(image.columns);
    image.departure_mm.assign(static_cast<std::size_t>(image.rows) * columns, kNoData);
    if (image.rows == 0 || columns == 0) return image;
    const std::vector<double>& depth = g.table().depth_m;
    const double band_m = std::abs(request.bottom_m - request.top_m) / image.rows;
    std::optional<std::size_t> previous;
    for (int r = 0; r < image.rows; ++r) {
        float* out = image.departure_mm.data() + static_cast<std::size_t>(r) * columns;
        const std::optional<std::size_t> row = nearestRow(depth, image.rowDepth_m(r), band_m / 2);
        if (!row) {
            previous.reset();
            continue;
        }
        if (previous && *previous == *row) {
            // A table coarser than the image: the row above is the same section.
            std::copy(out - columns, out, out);
            continue;
        }
        const double gauge = gaugeRadius_mm ? gaugeRadius_mm(*row) : g.bitRadius_mm(*row);
        fillRow(g, *row, gauge, request, out);
        previous = row;
    }
    return image;
}

}  // namespace caliper3d::reconstruction

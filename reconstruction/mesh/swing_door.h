#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

// Whether `row` must be kept at every level: a row without data or a gap's edge.
inline bool gapRow(const WellGeometry& g, std::size_t row) {
    const std::size_t rows = g.table().rowCount();
    return !g.measured(row) || (row > 0 && !g.measured(row - 1)) ||
           (row + 1 < rows && !g.measured(row + 1));
}

// The swing-door decimation of a segment's levels (lod_levels.cpp) and of the tree's spans
// (lod_tree.cpp), over `count` candidates: table rows `row(c)`, increasing, with knot `k` of
// candidate `c` at `value(c, k)` (read for measured candidates only). Returns the table rows
// kept, the first and last candidate among them. A candidate is left out while the straight
// line (in depth) between the kept candidates on either side stays within
// `level.tolerance_mm` of every one of its knots, and kept candidates lie at most
// `level.maxSpacing_m` apart (the next candidate is always allowed). A gap's row or edge
// (gapRow) is always kept, and so is the candidate before it when the line to it does not
// fit. A function template so that each caller reads its knots where it holds them, inline.
template <class Row, class Value>
std::vector<std::size_t> swingDoor(const WellGeometry& g, std::size_t count, Row row, Value value,
                                   std::size_t knots, const LodLevel& level) {
    std::vector<std::size_t> kept;
    if (count == 0) return kept;
    const std::vector<double>& depth = g.table().depth_m;
    const std::size_t last = count - 1;
    std::vector<double> lo(knots), hi(knots);
    kept.push_back(row(0));
    std::size_t anchor = 0;
    while (anchor < last) {
        std::fill(lo.begin(), lo.end(), -std::numeric_limits<double>::infinity());
        std::fill(hi.begin(), hi.end(), std::numeric_limits<double>::infinity());
        std::size_t best = anchor + 1;
        const bool anchorMeasured = g.measured(row(anchor));
        for (std::size_t c = anchor + 1; c <= last; ++c) {
            const double dd = depth[row(c)] - depth[row(anchor)];
            if (dd > level.maxSpacing_m && c > anchor + 1) break;
            if (!anchorMeasured || !g.measured(row(c)) || !(dd > 0.0)) {
                best = c;
                break;
            }
            // c may end the run when the straight line to it stays inside every corridor.
            // (Slopes times 1/dd, not divided by dd: three divisions a knot were most of a
            // field's planning; the corridors move by a rounding at most.)
            const double perMetre = 1.0 / dd;
            bool fits = true;
            for (std::size_t k = 0; k < knots && fits; ++k) {
                const double slope = (value(c, k) - value(anchor, k)) * perMetre;
                fits = slope >= lo[k] && slope <= hi[k];
            }
            if (!fits) break;
            best = c;
            if (c == last || gapRow(g, row(c))) break;
            bool open = true;
            for (std::size_t k = 0; k < knots; ++k) {
                lo[k] = std::max(lo[k],
                                 (value(c, k) - level.tolerance_mm - value(anchor, k)) * perMetre);
                hi[k] = std::min(hi[k],
                                 (value(c, k) + level.tolerance_mm - value(anchor, k)) * perMetre);
                open = open && lo[k] <= hi[k];
            }
            if (!open) break;
        }
        kept.push_back(row(best));
        anchor = best;
    }
    return kept;
}

}  // namespace caliper3d::reconstruction

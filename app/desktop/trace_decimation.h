#pragma once

#include <vector>

#include "app/desktop/row_curve.h"

namespace caliper3d::app {

struct TracePoint {
    double depth_m = 0.0;
    double value = 0.0;
};
// Consecutive rows with data: drawn as one line.
using TraceRun = std::vector<TracePoint>;

// The rows of a log curve between top_m and bottom_m, thinned for a plot `buckets` pixels
// tall: the depth range is cut into `buckets` equal spans and each span keeps only its
// smallest and largest value, in depth order (so a one-row spike still shows; a plot cannot
// show more than that in a pixel), and a run's first and last rows (so the line reaches its
// gaps). A 4 km log of 400,000 rows becomes some two points a pixel. Rows without data (NaN)
// split the curve into runs, never joined across, however short the gap. The row just above top_m
// and the one just below bottom_m are kept, so a line reaches the plot's edges. `depth_m`
// increases; `value` has the same length.
std::vector<TraceRun> decimateTrace(const RowCurve& depth_m, const RowCurve& value, double top_m,
                                    double bottom_m, int buckets);

}  // namespace caliper3d::app

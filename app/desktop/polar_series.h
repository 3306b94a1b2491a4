#pragma once

#include <vector>

#include <QList>
#include <QPointF>

#include "reconstruction/analysis/section_outline.h"

namespace caliper3d::app {

// Points for a QLineSeries on a QPolarChart whose angular axis runs over [0, 360]. The chart
// draws a step between points more than 180 degrees apart through the pole, so a line that
// crosses the 0-degree ray would get a spoke there: each such crossing becomes two points just
// off the axis's range, one either side of it, which the chart joins to the ray without a
// spoke (a segment to an off-range point stops at the ray; two off-range points in a row draw
// nothing). `closed`: the last point joins the first.
QList<QPointF> polarPolyline(const std::vector<reconstruction::PolarPoint>& points, bool closed);

}  // namespace caliper3d::app

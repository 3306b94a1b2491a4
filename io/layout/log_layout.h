#pragma once

#include <cstddef>
#include <vector>

#include "io/curve_plan.h"
#include "io/stream/row_parser.h"

namespace caliper3d::io {

// How a log's data is laid out, as a format's layout step decides it from the
// header or the first lines: the columns, which role each plays (the plan) and
// what a data line looks like (the row format).
struct LogLayout {
    std::vector<ColumnSpec> columns;
    CurvePlan plan;
    RowFormat format;
    std::size_t namesLines = 0;  // column text: lines before the data, names and comments
    bool radiiOnly = false;      // column text of radii only: depth = row x rowStep_m
};

}  // namespace caliper3d::io

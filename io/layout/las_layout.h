#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "io/diagnostics.h"
#include "io/las_header.h"
#include "io/layout/log_layout.h"
#include "io/log_info.h"
#include "io/read_options.h"

namespace caliper3d::io {

// "LAS 2.0", "LAS 1.2, wrapped".
std::string lasVersionText(const LasHeader& header);

// What a line (or, wrapped, a depth) of the ~A section holds: one value per
// ~C curve, the header's NULL and delimiter, the null policy (only the
// declared NULL when the header says so). The one row format of LAS, for the
// streamed caliper reader and readLas alike.
RowFormat lasRowFormat(const LasHeader& header, const std::vector<ColumnSpec>& columns,
                       NullPolicy policy, const std::string& file, int depthColumn);

// The layout of a LAS log from its parsed header: columns from ~C, the roles,
// the row format. Fills `info` (format, well name, location, curves and roles).
// Throws ParseError for a header without curves or with a caliper curve in an
// unknown unit.
LogLayout lasLayout(const LasHeader& header, const std::string& file, const ReadOptions& options,
                    LogInfo& info);

// LAS files may hold fewer data columns than ~C curves ("excess curves"): the
// first data line of `data` (line numbers after `linesBefore`) settles how
// many values a row holds, with a warning naming the curves without data.
// Throws when the depth curve is among those missing. Not for wrapped data.
void settleLasColumns(std::string_view data, std::size_t linesBefore,
                      const std::vector<ColumnSpec>& columns, RowFormat& format,
                      Diagnostics& diagnostics);

}  // namespace caliper3d::io

#pragma once

#include <string>
#include <string_view>

#include "io/layout/log_layout.h"
#include "io/log_info.h"
#include "io/read_options.h"

namespace caliper3d::io {

// The layout of column text, decided by its first lines (docs/formats.md):
// - a line of names with one name per column (or a '#' line of them right
//   before the data, starting with a depth) names the columns, each a
//   mnemonic with an optional unit ("R1_in", "BS(mm)"), roles as in LAS;
// - otherwise the reference layout, depth R1..RN P1AZ DEVI HAZI (N from
//   options.armCount);
// - or, for kMinRadiiOnlyColumns or more numbers but not N + 4, radii only
//   (depth = row x rowStep_m), with a warning.
// Without units, depths are metres and radii inches unless the first row's
// radii would be implausibly large (then millimetres, with a warning).
// `start` is the beginning of the text. Fills `info` (format, curves, units).
LogLayout columnTextLayout(std::string_view start, const std::string& file,
                           const ReadOptions& options, LogInfo& info);

}  // namespace caliper3d::io

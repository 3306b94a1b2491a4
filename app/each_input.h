#pragma once

#include <functional>
#include <string>
#include <vector>

#include "app/input_options.h"
#include "app/input_summary.h"

namespace caliper3d::app {

// What writes one well into its own output (export's scene, render's picture), adding its
// summary lines to `inputs`; returns the verb's exit status for that well.
using WriteOneInput = std::function<int(const WellSource& source, const std::string& output,
                                        std::vector<InputSummary>& inputs)>;

// Writes each of `sources` into `outputs[i]` with `write`, one after the other, with the
// terminal's progress line (app/progress_display.h) and each well's summary lines written to
// `summaries`; a well that fails does not stop the others. kExitBadInput when any failed.
int writeEachInput(const std::vector<WellSource>& sources, const std::vector<std::string>& outputs,
                   SummaryFile& summaries, const WriteOneInput& write);

}  // namespace caliper3d::app

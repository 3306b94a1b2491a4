#include "app/each_input.h"

#include "app/commands.h"
#include "app/progress_display.h"

namespace caliper3d::app {

int writeEachInput(const std::vector<WellSource>& sources, const std::vector<std::string>& outputs,
                   SummaryFile& summaries, const WriteOneInput& write) {
    ProgressDisplay progress(sources.size());
    int failures = 0;
    for (std::size_t i = 0; i < sources.size(); ++i) {
        const std::string& file = sources[i].path;
        progress.started(file, file);
        std::vector<InputSummary> inputs;
        const int status = write(sources[i], outputs[i], inputs);
        progress.clear();
        failures += status != kExitOk;
        for (const InputSummary& input : inputs) summaries.write(input);
        progress.finished(file, status == kExitOk);
    }
    return failures > 0 ? kExitBadInput : kExitOk;
}

}  // namespace caliper3d::app

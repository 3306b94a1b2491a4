#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/input_summary.h"
#include "app/well_option_table.h"
#include "reconstruction/analysis/run_change.h"
#include "reconstruction/analysis/well_analysis.h"
#include "reconstruction/load/load_well.h"

namespace caliper3d::app {

// `--colour-by change --compare-with RUN` for the verbs that draw (render, export): the other
// run read (with the drawn wells' reading options, no survey or wellhead of its own: only its
// sections are compared) and analysed once, then each drawn well analysed, depth-matched and
// compared with it as `caliper3d compare DRAWN RUN` would (docs/analysis.md, "Colour by
// change"). Prints one line per drawn well: the runs, the shift and the correlation.
class ChangeReference {
public:
    // Reads options.colour.compareWith; throws UsageError when it is not given, and the
    // reader's error (io::ParseError, naming file and line) for a bad file.
    explicit ChangeReference(const LoadOptions& options);

    // `drawn` (a whole log, before any --depth interval) against the other run.
    reconstruction::RunChange against(const reconstruction::WellGeometry& drawn) const;

    const std::string& path() const { return m_path; }

private:
    std::string m_path;
    reconstruction::LoadedWell m_other;
    reconstruction::WellAnalysis m_analysis;
    int m_threads = 1;
};

// What a --summary line says of a wall coloured by `change` against the run at `otherPath`.
ComparedRuns comparedRuns(const reconstruction::RunChange& change, const std::string& otherPath);

// True when `options` asks for the wall coloured by change.
bool coloursByChange(const LoadOptions& options);
// Throws UsageError for --compare-with without --colour-by change, or the reverse.
void checkChangeOptions(const LoadOptions& options, const std::string& verb);

}  // namespace caliper3d::app

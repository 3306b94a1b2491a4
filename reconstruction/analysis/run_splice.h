#pragma once

#include <cstddef>
#include <vector>

#include "io/section_table.h"
#include "reconstruction/analysis/depth_match.h"

namespace caliper3d::reconstruction {

// Where one run joins the log spliced from the runs before it (docs/analysis.md, "Splicing
// runs"). Depths are the spliced log's: the first run's.
struct SpliceJoin {
    std::size_t run = 0;   // index of the run joined (1 for the second)
    DepthMapping mapping;  // this run against the one before: md_this = mapping.toRun2(md_before)
    // This run's depth d lies at log depth (d - appliedShift_m) / (1 + stretch) as applied: the
    // shifts of every join so far, each rounded to whole sampling steps where the runs share one
    // (the log keeps one step) unless SpliceOptions::exactShift.
    double appliedShift_m = 0.0;
    double stretch = 0.0;
    double overlapTop_m = 0.0, overlapBottom_m = 0.0;
    // Rows of the log so far above at_m, this run's rows from at_m on; a run that ends above
    // the log so far (a repeat over a bad interval) replaces it over [at_m, until_m] only.
    double at_m = 0.0;
    double until_m = io::kNaN;  // NaN: to this run's end
};

struct SpliceOptions {
    // One per join: the log depth to join at; NaN (or missing) for the overlap's middle.
    std::vector<double> at_m;
    bool exactShift = false;  // keep each matched shift as measured (the step may vary at joins)
};

struct SplicedLog {
    // Every run's curves (NaN where a run lacks one; the bit size row by row) and curve RUN;
    // each run's casing program in the log's depths, holding over that run's rows only
    // (io::CasingString::appliesFrom_m, appliesTo_m).
    io::SectionTable table;
    std::vector<SpliceJoin> joins;
};

// Splices runs of one well, given from the shallowest, into one log: run k + 1's depths are
// mapped onto run k's by mappings[k], rows keep their own run's radii, orientation, bit size
// and curves, and an extra curve RUN numbers the run each row came from (1 for the first).
// Throws std::runtime_error when the runs' arm counts differ, when a run starts above the log
// spliced so far, when a join depth lies outside its overlap, or when two runs do not overlap.
SplicedLog spliceRuns(const std::vector<const io::SectionTable*>& runs,
                      const std::vector<DepthMapping>& mappings, const SpliceOptions& options = {});

}  // namespace caliper3d::reconstruction

#pragma once

#include <ostream>
#include <string>

#include "reconstruction/analysis/run_comparison.h"

namespace caliper3d::reconstruction {

// The comparison CSV (docs/analysis.md, "The compare report"): one header line, then one row per
// depth of the overlap (run 1's sampling):
//   md_m,md2_m,deq1_mm,deq2_mm,d_deq_mm,dmin1_mm,dmin2_mm,d_dmin_mm,dmax1_mm,dmax2_mm,d_dmax_mm,
//   class1,class2,
// then major_azimuth1_deg,major_azimuth2_deg,d_major_azimuth_deg,area1_mm2,area2_mm2,
//   d_area_mm2,d_area_pct,d_deq_pct,max_growth_mm,max_growth_azimuth_deg,significant,note.
// Differences are run 2 minus run 1; an undefined value is an empty field; `note` says why a
// depth is not compared, why its azimuths are unknown or why its outline was not compared
// (RunComparisonOptions::outlineGate). Decimal point whatever the locale. Rows are formatted
// in blocks, `threads` blocks at once, and written in order.
void writeComparisonCsv(std::ostream& out, const RunComparison& comparison, int threads = 1);
// The same to a file, whole or not at all (io/atomic_output.h).
void writeComparisonCsv(const std::string& path, const RunComparison& comparison, int threads = 1);

// The zones table: change,class,top1_m,bottom1_m,top2_m,bottom2_m,length1_m,length2_m,
// mean_d_deq_mm,max_d_dmax_mm,max_d_dmax_md_m: the class zones of either run paired
// (appeared, grew, shrank, unchanged, closed), then the intervals that changed beyond the
// repeatability (change "changed", no class).
void writeZoneChanges(std::ostream& out, const RunComparison& comparison);
void writeZoneChanges(const std::string& path, const RunComparison& comparison);

// The human summary: depth match, stretch, overlap, biases, threshold, largest changes, zones,
// class changes, volumes and whether the runs agree; several "key: value" lines.
std::string formatComparisonSummary(const RunComparison& comparison);

}  // namespace caliper3d::reconstruction

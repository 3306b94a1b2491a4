#pragma once

#include "io/diagnostics.h"
#include "reconstruction/analysis/well_analysis.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

// The warnings a well's reconstruction gives beside its reader's, added to the
// same Diagnostics so that the count a command prints is the count of what it
// prints: one per no-data interval, and one for the interpolated arms.
// Scans every row for interpolated arms (what a verb without analysis needs).
void warnGeometry(const WellGeometry& geometry, io::Diagnostics& diagnostics);
// The same from an analysis of that geometry (its counts, no rescan), plus
// unoriented sections and a gauge taken from the sections.
void warnAnalysis(const WellGeometry& geometry, const WellAnalysis& analysis,
                  io::Diagnostics& diagnostics);

}  // namespace caliper3d::reconstruction

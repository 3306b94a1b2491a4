#pragma once

#include <string>

#include "io/section_table.h"
#include "reconstruction/analysis/depth_match.h"
#include "reconstruction/analysis/well_analysis.h"

namespace caliper3d::reconstruction {

// The name that stands for the equivalent diameter of the analysed sections.
inline constexpr const char* kEquivalentDiameterCurve = "deq";

// The curve two runs are depth-matched on (docs/analysis.md, "Depth matching"): `asked` when
// given (a curve both logs carry, by mnemonic, any case; or "deq"); else the gamma ray when
// both carry one (GR, or a mnemonic starting with GR), else "deq". Returns the first run's
// mnemonic, or "deq". Throws std::runtime_error naming the log that lacks an asked curve.
std::string chooseMatchCurve(const io::SectionTable& run1, const io::SectionTable& run2,
                             const std::string& asked);

// That curve of one run: an extra curve by mnemonic (any case), or for "deq" the analysed
// equivalent diameter (NaN where a section has none: no data, cased).
DepthCurve matchCurveOf(const io::SectionTable& table, const WellAnalysis& analysis,
                        const std::string& name);

}  // namespace caliper3d::reconstruction

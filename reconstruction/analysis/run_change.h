#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "reconstruction/analysis/run_comparison.h"
#include "reconstruction/mesh/wall_colouring.h"

namespace caliper3d::reconstruction {

// How two runs of one well are depth-matched (compare's --match-curve, --max-shift, --shift,
// --no-stretch; docs/analysis.md, "Depth matching").
struct RunMatchRequest {
    std::string curve;  // a mnemonic both logs carry, or "deq"; empty: GR when both, else deq
    double maxShift_m = 2.0;
    std::optional<double> shift_m;  // taken as given: no matching, no stretch
    bool allowStretch = true;
    int threads = 1;  // DepthMatchOptions::threads
};

// Where each depth of run 1 lies in run 2, as `caliper3d compare` finds it (chooseMatchCurve,
// fitDepthMapping). Throws std::runtime_error as they do (a curve one log lacks, a flat curve,
// runs that do not overlap).
DepthMapping matchRuns(const ComparedRun& run1, const ComparedRun& run2,
                       const RunMatchRequest& request = {});

// The repeat-pass limit two runs are held to: the larger of their tools' (repeatabilityLimit_mm).
double repeatabilityLimit_mm(const ComparedRun& run1, const ComparedRun& run2);

// One run's wall against another run of the same well, depth by depth of the drawn run
// (docs/analysis.md, "Colour by change"): the equivalent-diameter change, drawn minus other,
// from compareRuns with the drawn run as run 1 (so its bias removal, its interpolation of the
// other run at the matched depth and its "not compared" rules hold).
struct RunChange {
    std::string drawnName, otherName;  // as the legend names the runs (their files' names)
    DepthMapping mapping;              // where a depth of the drawn run lies in the other
    double repeatability95_mm = 0.0;
    std::vector<double> md_m;      // the drawn run's depths that the other run also logged
    std::vector<float> change_mm;  // drawn minus other; NaN where not compared
    std::size_t compared = 0;      // depths with a change
    // Where both runs are oriented to north: the wall's movement at each direction, drawn minus
    // other (mm, half a diameter's change), per md_m: bins clockwise from north
    // (DirectionalValues: bin b centred at (b + 0.5) * 360 / bins). slot -1: not compared so.
    DirectionalValues directions;
    // The comparison's figures (summary, zones, largest changes: run 2, the other, minus
    // run 1, the drawn run), its per-depth sections left out.
    std::shared_ptr<const RunComparison> figures;
};
// Matches and compares `other` against `drawn` (threads: compareRuns's chunks).
RunChange measureRunChange(const ComparedRun& drawn, const ComparedRun& other,
                           std::string drawnName, std::string otherName,
                           const RunMatchRequest& match = {}, int threads = 1);
// The same from a comparison already made with the drawn run as run 1.
RunChange runChangeOf(RunComparison comparison, std::string drawnName, std::string otherName);

// The colour-map bins of the wall's movement: 36, 10 degrees each.
inline constexpr int kChangeDirectionBins = 36;

// The change at each of `depth_m` (a drawn geometry's rows: its whole log or an interval of
// it): that of the compared depth within 1 mm of it; NaN where there is none (outside the
// overlap) or it was not compared.
std::vector<float> changeAtDepths(const RunChange& change, const std::vector<double>& depth_m);

// The drawn wall coloured by `change` on the diverging map (docs/analysis.md, "Colour by
// change"): how far the wall moved, drawn minus other, in mm. Where both runs are oriented to
// north, at each azimuth (10-degree bins of RunChange::directions, about the section's
// centre); elsewhere the mean, half the equivalent diameter's change, round the whole section.
// Grey (0) where the runs agree, symmetric about 0 over +-(the 98th percentile of |movement|,
// at least half the repeatability limit) unless `range` is given (it must hold 0). Sections
// without a change take kNoValueColour, and the legend ("A minus B", mm) says why. Throws
// std::invalid_argument for a range that does not hold 0.
std::shared_ptr<const WallColouring> changeColouring(
    const WellGeometry& drawn, const RunChange& change,
    const std::optional<std::pair<double, double>>& range = std::nullopt);

// Each drawn well against its change, one range for all (the widest of their own, unless
// given), so a colour means the same change in each.
std::vector<std::shared_ptr<const WallColouring>> changeColourings(
    const std::vector<std::shared_ptr<const WellGeometry>>& drawn,
    const std::vector<const RunChange*>& changes,
    const std::optional<std::pair<double, double>>& range = std::nullopt);

}  // namespace caliper3d::reconstruction

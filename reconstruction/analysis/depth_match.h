#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "io/section_table.h"

namespace caliper3d::reconstruction {

// A curve along measured depth, as a log gives it: depths increasing, NaN where nothing was
// read.
struct DepthCurve {
    std::vector<double> depth_m;
    std::vector<double> values;
};

struct DepthMatchOptions {
    // The shift is sought in [centre_m - maxShift_m, centre_m + maxShift_m] (docs/analysis.md,
    // "Two runs of one well": 0.5-3 m between runs is common).
    double maxShift_m = 2.0;
    double centre_m = 0.0;
    // Only curve 1 between these depths takes part (a tie window); the whole curve by default.
    double top_m = -1.0e300;
    double bottom_m = 1.0e300;
    // Workers for the correlation at each lag (and, in fitDepthMapping, the two tie windows side
    // by side); the result does not depend on it.
    int threads = 1;
};

// The shift of curve 2 against curve 1 that best aligns them: the feature at depth d of curve 1
// lies at d + shift_m on curve 2 (a second run whose counter reads deeper has a positive shift).
struct DepthMatch {
    double shift_m = io::kNaN;
    double correlation = io::kNaN;  // normalised cross-correlation (Pearson) at that shift
    std::size_t samples = 0;        // curve 1's samples compared at that shift
};

// Normalised cross-correlation of the two curves over a search window, on a grid about 1 % of
// the window apart (the curves averaged into its cells), then refined below the sampling step
// by Brent's method on the correlation of curve 1's own samples with curve 2 interpolated
// linearly at the shifted depths. Throws std::runtime_error when the curves do not overlap at
// any shift of the window, or when either is flat (constant or unread) where they do.
DepthMatch matchDepths(const DepthCurve& curve1, const DepthCurve& curve2,
                       const DepthMatchOptions& options = {});

// Pearson correlation of curve 1's samples in [top_m, bottom_m] with curve 2 read at
// depth + shift_m (linear interpolation); `samples` receives how many pairs took part. NaN
// where fewer than two pairs or either side is flat.
double shiftedCorrelation(const DepthCurve& curve1, const DepthCurve& curve2, double shift_m,
                          double top_m, double bottom_m, std::size_t* samples = nullptr);

// One tie point of a stretch: the shift measured over a window of curve 1 centred at md1_m.
struct DepthTie {
    double md1_m = 0.0;
    DepthMatch match;
};

// Where a depth of run 1 lies in run 2: md2 = md1 + shift_m + stretch * (md1 - reference_m)
// (docs/analysis.md, "Depth matching").
struct DepthMapping {
    double shift_m = 0.0;
    double stretch = 0.0;  // metres of run 2 per metre of run 1, minus one
    double reference_m = 0.0;
    bool given = false;  // the shift was given (--shift), not measured
    DepthMatch match;    // the match over the whole overlap (not set when given)
    // The two tie windows' matches when the overlap was long enough to measure them (empty
    // otherwise); the stretch is the line through them when they disagree.
    std::vector<DepthTie> ties;
    std::string curve;  // what was correlated ("GR", "equivalent diameter", ...)

    double toRun2(double md1_m) const { return md1_m + shift_m + stretch * (md1_m - reference_m); }
    double toRun1(double md2_m) const {
        return (md2_m - shift_m + stretch * reference_m) / (1.0 + stretch);
    }
};

struct DepthMappingOptions {
    DepthMatchOptions match;
    // A stretch is measured when the overlap is at least this long: the shift over its top
    // third and over its bottom third, each sought within maxShift_m of the whole overlap's.
    double minStretchInterval_m = 100.0;
    // ... and applied when both ties correlate at least this well and differ by more than
    // stretchTolerance_m (twice what one match resolves).
    double minTieCorrelation = 0.5;
    double stretchTolerance_m = 0.02;
    bool allowStretch = true;
};

// The shift over the whole overlap, and where the overlap is long, the stretch between two
// tie points (docs/analysis.md, "Depth matching").
DepthMapping fitDepthMapping(const DepthCurve& curve1, const DepthCurve& curve2,
                             const DepthMappingOptions& options = {});

}  // namespace caliper3d::reconstruction

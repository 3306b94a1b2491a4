#include "reconstruction/analysis/run_change.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "reconstruction/analysis/match_curve.h"
#include "reconstruction/analysis/wall_colour_request.h"

namespace caliper3d::reconstruction {

namespace {

constexpr float kNaNf = std::numeric_limits<float>::quiet_NaN();
// A drawn row takes the change of the compared depth this close to it (both are the drawn
// run's own depths, an interval's rows copied from the whole log's).
constexpr double kSameDepth_m = 0.001;

// The half-width of the default range: the 98th percentile of |change| over `values` (a few
// extreme sections do not wash the rest into one colour), at least the repeatability limit
// (changes within the tool's repeatability stay near grey).
double halfRange(const std::vector<float>& values, double repeatability_mm) {
    std::vector<float> magnitude;
    magnitude.reserve(values.size());
    for (const float v : values)
        if (std::isfinite(v)) magnitude.push_back(std::abs(v));
    const double p98 = robustPercentile(std::move(magnitude), 0.98);
    const double floor = repeatability_mm > 0.0 ? repeatability_mm : 1.0;
    return std::isfinite(p98) ? std::max(p98, floor) : floor;
}

std::string signedMetres(double v) {
    if (std::abs(v) < 0.0005) v = 0.0;  // not "-0.000"
    char text[32];
    std::snprintf(text, sizeof text, "%+.3f m", v);
    return text;
}

ColourLegend changeLegend(const RunChange& change, std::string range) {
    ColourLegend legend;
    legend.title = change.drawnName + " minus " + change.otherName;
    legend.unit = "mm";
    legend.range = std::move(range);
    legend.centre = "no change";
    // Short lines: the panel must leave the picture's middle to the well.
    legend.note = "equiv. diameter, shift " + signedMetres(change.mapping.shift_m) +
                  (change.mapping.given ? " (given)" : "");
    legend.noValueText = "not compared:\nno overlap, no data,\narms not open, cased";
    return legend;
}

void checkRange(const std::pair<double, double>& range) {
    if (!(range.first < 0.0 && range.second > 0.0))
        throw std::invalid_argument(
            "--colour-range: changes are drawn either side of no change, so LO must be below 0 "
            "and HI above it");
}

}  // namespace

DepthMapping matchRuns(const ComparedRun& run1, const ComparedRun& run2,
                       const RunMatchRequest& request) {
    DepthMapping mapping;
    if (request.shift_m) {
        mapping.shift_m = *request.shift_m;
        mapping.given = true;
        return mapping;
    }
    const io::SectionTable& t1 = run1.geometry->table();
    const io::SectionTable& t2 = run2.geometry->table();
    const std::string curve = chooseMatchCurve(t1, t2, request.curve);
    DepthMappingOptions options;
    options.match.maxShift_m = request.maxShift_m;
    options.allowStretch = request.allowStretch;
    mapping = fitDepthMapping(matchCurveOf(t1, *run1.analysis, curve),
                              matchCurveOf(t2, *run2.analysis, curve), options);
    mapping.curve = curve == kEquivalentDiameterCurve ? "equivalent diameter" : curve;
    return mapping;
}

double repeatabilityLimit_mm(const ComparedRun& run1, const ComparedRun& run2) {
    return std::max(repeatabilityLimit_mm(run1.geometry->table().armCount),
                    repeatabilityLimit_mm(run2.geometry->table().armCount));
}

RunChange runChangeOf(RunComparison comparison, std::string drawnName, std::string otherName) {
    RunChange out;
    out.drawnName = std::move(drawnName);
    out.otherName = std::move(otherName);
    out.mapping = comparison.mapping;
    out.repeatability95_mm = comparison.repeatability95_mm;
    out.md_m.reserve(comparison.sections.size());
    out.change_mm.reserve(comparison.sections.size());
    for (const SectionChange& s : comparison.sections) {
        out.md_m.push_back(s.md1_m);
        // The comparison's changes are run 2 (the other) minus run 1 (the drawn run).
        const double change = s.compared() ? s.deq1_mm - s.deq2_mm : io::kNaN;
        out.change_mm.push_back(static_cast<float>(change));
        if (std::isfinite(change)) ++out.compared;
    }
    comparison.sections = {};
    out.figures = std::make_shared<const RunComparison>(std::move(comparison));
    return out;
}

RunChange measureRunChange(const ComparedRun& drawn, const ComparedRun& other,
                           std::string drawnName, std::string otherName,
                           const RunMatchRequest& match, int threads) {
    RunComparisonOptions options;
    options.mapping = matchRuns(drawn, other, match);
    options.repeatability95_mm = repeatabilityLimit_mm(drawn, other);
    options.threads = std::max(1, threads);
    return runChangeOf(compareRuns(drawn, other, options), std::move(drawnName),
                       std::move(otherName));
}

std::vector<float> changeAtDepths(const RunChange& change, const std::vector<double>& depth_m) {
    std::vector<float> out(depth_m.size(), kNaNf);
    const std::vector<double>& md = change.md_m;
    for (std::size_t row = 0; row < depth_m.size(); ++row) {
        const double d = depth_m[row];
        auto at = std::lower_bound(md.begin(), md.end(), d - kSameDepth_m);
        if (at != md.end() && *at <= d + kSameDepth_m)
            out[row] = change.change_mm[static_cast<std::size_t>(at - md.begin())];
    }
    return out;
}

std::shared_ptr<const WallColouring> changeColouring(
    const WellGeometry& drawn, const RunChange& change,
    const std::optional<std::pair<double, double>>& range) {
    std::vector<float> values = changeAtDepths(change, drawn.table().depth_m);
    double lo = 0.0, hi = 0.0;
    std::string rangeText;
    if (range) {
        checkRange(*range);
        std::tie(lo, hi) = *range;
        rangeText = "given";
    } else {
        hi = halfRange(values, change.repeatability95_mm);
        lo = -hi;
        char text[96];
        std::snprintf(text, sizeof text, "98th pct, at least %.1f mm", change.repeatability95_mm);
        rangeText = text;
    }
    ColourLegend legend = changeLegend(change, std::move(rangeText));
    for (std::size_t row = 0; row < values.size(); ++row)
        legend.noValue = legend.noValue || (drawn.measured(row) && !std::isfinite(values[row]));
    return std::make_shared<const WallColouring>(WallColouring::perRow(
        std::move(values), ColourMapKind::Diverging, lo, hi, std::move(legend)));
}

std::vector<std::shared_ptr<const WallColouring>> changeColourings(
    const std::vector<std::shared_ptr<const WellGeometry>>& drawn,
    const std::vector<const RunChange*>& changes,
    const std::optional<std::pair<double, double>>& range) {
    if (drawn.size() != changes.size())
        throw std::invalid_argument("changeColourings: one change per drawn well");
    std::vector<std::shared_ptr<const WallColouring>> out;
    for (std::size_t w = 0; w < drawn.size(); ++w)
        out.push_back(changeColouring(*drawn[w], *changes[w], range));
    if (out.size() < 2 || range) return out;
    double half = 0.0;
    for (const auto& colouring : out) half = std::max(half, colouring->legend().hi);
    for (std::size_t w = 0; w < drawn.size(); ++w) {
        auto shared = changeColouring(*drawn[w], *changes[w], std::make_pair(-half, half));
        ColourLegend legend = shared->legend();
        legend.range =
            out[w]->legend().range + ", over all " + std::to_string(drawn.size()) + " wells";
        out[w] = std::make_shared<const WallColouring>(shared->withLegend(std::move(legend)));
    }
    return out;
}

}  // namespace caliper3d::reconstruction

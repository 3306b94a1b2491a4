#include "reconstruction/analysis/run_change.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "reconstruction/analysis/match_curve.h"
#include "reconstruction/analysis/section_angle_reference.h"
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

ColourLegend changeLegend(const RunChange& change, std::string range, bool anyUndirected) {
    ColourLegend legend;
    legend.title = change.drawnName + " minus " + change.otherName;
    legend.unit = "mm";
    legend.range = std::move(range);
    legend.centre = "no change";
    // Short lines: the panel must leave the picture's middle to the well.
    legend.note = std::string(anyUndirected ? "wall movement (mean where unoriented)"
                                            : "wall movement at each azimuth") +
                  ", shift " + signedMetres(change.mapping.shift_m) +
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
    options.match.threads = request.threads;
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
    RunMatchRequest request = match;
    request.threads = std::max(1, threads);
    options.mapping = matchRuns(drawn, other, request);
    options.repeatability95_mm = repeatabilityLimit_mm(drawn, other);
    options.threads = std::max(1, threads);
    // The wall's movement at each direction, per section of the drawn run, 36 bins of 10
    // degrees from the comparison's 72 samples every 5 degrees: bin b is the sample at its
    // centre, 10 b + 5, smoothed with its neighbours (1/4, 1/2, 1/4). Drawn minus other.
    const SectionResults& sections = drawn.analysis->sections;
    constexpr int kBins = kChangeDirectionBins;
    options.azimuthBins = 2 * kBins;
    const float step = DirectionalValues{}.step;
    std::vector<std::int16_t> dense(sections.size() * kBins, kNoDirectionalValue);
    options.outlineSink = [&dense, step](std::size_t row, const double* growth) {
        for (int b = 0; b < kBins; ++b) {
            const double g = 0.25 * growth[2 * b] + 0.5 * growth[2 * b + 1] +
                             0.25 * growth[(2 * b + 2) % (2 * kBins)];
            const double q = std::round(-g / step);
            dense[row * kBins + static_cast<std::size_t>(b)] =
                static_cast<std::int16_t>(std::clamp(q, -32767.0, 32767.0));
        }
    };
    RunChange out =
        runChangeOf(compareRuns(drawn, other, options), std::move(drawnName), std::move(otherName));
    // The compared depths are sections of the drawn run, in order.
    DirectionalValues& d = out.directions;
    d.bins = kBins;
    d.slot.assign(out.md_m.size(), -1);
    std::size_t row = 0;
    for (std::size_t k = 0; k < out.md_m.size(); ++k) {
        while (row < sections.size() && sections.md_m(row) < out.md_m[k]) ++row;
        if (row == sections.size()) break;
        const std::int16_t* values = &dense[row * kBins];
        if (values[0] == kNoDirectionalValue || !std::isfinite(out.change_mm[k])) continue;
        d.slot[k] = static_cast<std::int32_t>(d.values.size() / kBins);
        d.values.insert(d.values.end(), values, values + kBins);
    }
    return out;
}

namespace {

// The index into change.md_m of the compared depth within kSameDepth_m of each of `depth_m`;
// -1 where there is none.
std::vector<std::int64_t> comparedIndices(const RunChange& change,
                                          const std::vector<double>& depth_m) {
    std::vector<std::int64_t> out(depth_m.size(), -1);
    const std::vector<double>& md = change.md_m;
    for (std::size_t row = 0; row < depth_m.size(); ++row) {
        const double d = depth_m[row];
        auto at = std::lower_bound(md.begin(), md.end(), d - kSameDepth_m);
        if (at != md.end() && *at <= d + kSameDepth_m) out[row] = at - md.begin();
    }
    return out;
}

// The drawn run's movement of the wall: per row half its equivalent diameter's change, and
// where both runs are oriented to north its movement at each direction.
struct WallMovement {
    std::vector<float> rowValues;
    DirectionalValues directions;
    bool anyUndirected = false;  // a row with a value but no directions
};

WallMovement wallMovement(const WellGeometry& drawn, const RunChange& change) {
    const std::vector<std::int64_t> at = comparedIndices(change, drawn.table().depth_m);
    const DirectionalValues& from = change.directions;
    const auto bins = static_cast<std::size_t>(from.bins);
    WallMovement out;
    out.rowValues.assign(at.size(), kNaNf);
    out.directions.bins = from.bins;
    out.directions.step = from.step;
    out.directions.slot.assign(at.size(), -1);
    for (std::size_t row = 0; row < at.size(); ++row) {
        if (at[row] < 0) continue;
        const auto k = static_cast<std::size_t>(at[row]);
        out.rowValues[row] = change.change_mm[k] / 2.0f;
        const std::int32_t slot = k < from.slot.size() ? from.slot[k] : -1;
        const double arm1 =
            slot >= 0 ? arm1Angle_deg(drawn.frame(row), AngleReference::North) : io::kNaN;
        if (!std::isfinite(arm1)) {
            out.anyUndirected = out.anyUndirected || std::isfinite(out.rowValues[row]);
            continue;
        }
        out.directions.slot[row] = static_cast<std::int32_t>(out.directions.arm1Angle_deg.size());
        out.directions.arm1Angle_deg.push_back(static_cast<float>(arm1));
        const auto* values = &from.values[static_cast<std::size_t>(slot) * bins];
        out.directions.values.insert(out.directions.values.end(), values, values + bins);
    }
    return out;
}

// The values the default range is taken over: each row's own where it has no directions,
// its directions' (of at most about 50,000 rows, evenly spread) where it has.
std::vector<float> rangeSample(const WallMovement& m) {
    std::vector<float> out;
    const std::size_t rows = m.rowValues.size();
    const std::size_t stride = std::max<std::size_t>(1, rows / 50000);
    const auto bins = static_cast<std::size_t>(m.directions.bins);
    for (std::size_t row = 0; row < rows; ++row) {
        const std::int32_t slot = m.directions.slot[row];
        if (slot < 0) {
            out.push_back(m.rowValues[row]);
        } else if (row % stride == 0) {
            for (std::size_t b = 0; b < bins; ++b)
                out.push_back(static_cast<float>(
                    m.directions.values[static_cast<std::size_t>(slot) * bins + b] *
                    m.directions.step));
        }
    }
    return out;
}

}  // namespace

std::vector<float> changeAtDepths(const RunChange& change, const std::vector<double>& depth_m) {
    const std::vector<std::int64_t> at = comparedIndices(change, depth_m);
    std::vector<float> out(depth_m.size(), kNaNf);
    for (std::size_t row = 0; row < at.size(); ++row)
        if (at[row] >= 0) out[row] = change.change_mm[static_cast<std::size_t>(at[row])];
    return out;
}

std::shared_ptr<const WallColouring> changeColouring(
    const WellGeometry& drawn, const RunChange& change,
    const std::optional<std::pair<double, double>>& range) {
    WallMovement movement = wallMovement(drawn, change);
    // Changes within the tool's repeatability stay near grey: half the diameter's limit, as
    // the wall moves half a diameter's change.
    const double floor_mm = change.repeatability95_mm / 2.0;
    double lo = 0.0, hi = 0.0;
    std::string rangeText;
    if (range) {
        checkRange(*range);
        std::tie(lo, hi) = *range;
        rangeText = "given";
    } else {
        hi = halfRange(rangeSample(movement), floor_mm);
        lo = -hi;
        char text[96];
        std::snprintf(text, sizeof text, "98th pct, at least %.1f mm", floor_mm);
        rangeText = text;
    }
    ColourLegend legend = changeLegend(change, std::move(rangeText), movement.anyUndirected);
    for (std::size_t row = 0; row < movement.rowValues.size(); ++row)
        legend.noValue =
            legend.noValue || (drawn.measured(row) && !std::isfinite(movement.rowValues[row]));
    return std::make_shared<const WallColouring>(
        WallColouring::perDirection(std::move(movement.rowValues), std::move(movement.directions),
                                    ColourMapKind::Diverging, lo, hi, std::move(legend)));
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

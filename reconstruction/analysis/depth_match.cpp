#include "reconstruction/analysis/depth_match.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <boost/math/tools/minima.hpp>

#include "reconstruction/parallel/ordered_blocks.h"

namespace caliper3d::reconstruction {

namespace {

// The depths over which a curve has readings: its first and last finite value (NaN, NaN when
// none) among the samples in [top, bottom].
std::pair<double, double> readRange(const DepthCurve& c, double top, double bottom) {
    double lo = io::kNaN, hi = io::kNaN;
    for (std::size_t i = 0; i < c.depth_m.size(); ++i) {
        const double d = c.depth_m[i];
        if (d < top || d > bottom || !std::isfinite(c.values[i])) continue;
        if (std::isnan(lo)) lo = d;
        hi = d;
    }
    return {lo, hi};
}

// The median spacing of a curve's depths (0 for fewer than two).
double medianStep(const std::vector<double>& depth) {
    if (depth.size() < 2) return 0.0;
    std::vector<double> steps;
    const std::size_t stride = std::max<std::size_t>(1, depth.size() / 2001);
    for (std::size_t i = stride; i < depth.size(); i += stride)
        steps.push_back((depth[i] - depth[i - stride]) / static_cast<double>(stride));
    std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2),
                     steps.end());
    return steps[steps.size() / 2];
}

// The curve on a grid of cells [origin + k*h, origin + (k+1)*h), k = 0..n-1: the mean of its
// samples in the cell, or where a cell holds none (a curve sampled more coarsely than the
// grid), the linear interpolation at its centre between two readings at most `maxGap` apart;
// NaN elsewhere. Values are taken about `centre` (numerically steadier sums).
std::vector<double> cellMeans(const DepthCurve& c, double origin, double h, std::size_t n,
                              double maxGap, double centre) {
    std::vector<double> sum(n, 0.0);
    std::vector<std::uint32_t> count(n, 0);
    for (std::size_t i = 0; i < c.depth_m.size(); ++i) {
        if (!std::isfinite(c.values[i])) continue;
        const double k = std::floor((c.depth_m[i] - origin) / h);
        if (k < 0.0 || k >= static_cast<double>(n)) continue;
        sum[static_cast<std::size_t>(k)] += c.values[i] - centre;
        ++count[static_cast<std::size_t>(k)];
    }
    std::vector<double> out(n, io::kNaN);
    std::size_t j = 0;  // first sample deeper than the cell's centre
    for (std::size_t k = 0; k < n; ++k) {
        if (count[k] > 0) {
            out[k] = sum[k] / count[k];
            continue;
        }
        const double x = origin + (static_cast<double>(k) + 0.5) * h;
        while (j < c.depth_m.size() && c.depth_m[j] <= x) ++j;
        if (j == 0 || j == c.depth_m.size()) continue;
        const double d0 = c.depth_m[j - 1], d1 = c.depth_m[j];
        const double v0 = c.values[j - 1], v1 = c.values[j];
        if (!std::isfinite(v0) || !std::isfinite(v1) || d1 - d0 > maxGap || !(d1 > d0)) continue;
        out[k] = v0 + (v1 - v0) * (x - d0) / (d1 - d0) - centre;
    }
    return out;
}

// Running sums of a Pearson correlation.
struct PearsonSums {
    double n = 0.0, x = 0.0, y = 0.0, xx = 0.0, yy = 0.0, xy = 0.0;
    void add(double a, double b) {
        n += 1.0;
        x += a;
        y += b;
        xx += a * a;
        yy += b * b;
        xy += a * b;
    }
    double correlation() const {
        const double vx = n * xx - x * x, vy = n * yy - y * y;
        if (n < 2.0 || !(vx > 0.0) || !(vy > 0.0)) return io::kNaN;
        return (n * xy - x * y) / std::sqrt(vx * vy);
    }
};

// A typical value of the curve (its first reading): the sums are taken about it.
double firstReading(const DepthCurve& c) {
    for (double v : c.values)
        if (std::isfinite(v)) return v;
    return 0.0;
}

std::string describeRange(double lo, double hi) {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(2);
    s << lo << "-" << hi << " m";
    return s.str();
}

}  // namespace

double shiftedCorrelation(const DepthCurve& c1, const DepthCurve& c2, double shift, double top,
                          double bottom, std::size_t* samples) {
    PearsonSums sums;
    const double centre1 = firstReading(c1), centre2 = firstReading(c2);
    std::size_t j = 0;
    const std::size_t n2 = c2.depth_m.size();
    for (std::size_t i = 0; i < c1.depth_m.size(); ++i) {
        const double d = c1.depth_m[i];
        if (d < top || d > bottom || !std::isfinite(c1.values[i])) continue;
        const double x = d + shift;
        while (j < n2 && c2.depth_m[j] < x) ++j;
        double v = io::kNaN;
        if (j < n2 && c2.depth_m[j] == x) {
            v = c2.values[j];
        } else if (j > 0 && j < n2) {
            const double d0 = c2.depth_m[j - 1], d1 = c2.depth_m[j];
            v = c2.values[j - 1] + (c2.values[j] - c2.values[j - 1]) * (x - d0) / (d1 - d0);
        }
        if (!std::isfinite(v)) continue;
        sums.add(c1.values[i] - centre1, v - centre2);
    }
    if (samples) *samples = static_cast<std::size_t>(sums.n);
    return sums.correlation();
}

DepthMatch matchDepths(const DepthCurve& c1, const DepthCurve& c2, const DepthMatchOptions& o) {
    if (c1.depth_m.size() != c1.values.size() || c2.depth_m.size() != c2.values.size())
        throw std::invalid_argument("matchDepths: a curve's depths and values differ in length");
    const auto [lo1, hi1] = readRange(c1, o.top_m, o.bottom_m);
    const auto [lo2, hi2] = readRange(c2, -1.0e300, 1.0e300);
    if (std::isnan(lo1) || std::isnan(lo2))
        throw std::runtime_error(
            "cannot match depths: " + std::string(std::isnan(lo1) ? "run 1" : "run 2") +
            " has no reading of the curve");
    const double lowest = o.centre_m - o.maxShift_m, highest = o.centre_m + o.maxShift_m;
    // The runs overlap at some shift s in [lowest, highest] when lo2 - s < hi1 and hi2 - s > lo1.
    if (!(lo2 - highest < hi1 && hi2 - lowest > lo1))
        throw std::runtime_error("the runs do not overlap: run 1 reads " + describeRange(lo1, hi1) +
                                 ", run 2 " + describeRange(lo2, hi2) +
                                 ", and the shifts searched reach only " +
                                 describeRange(lowest, highest));

    const double step1 = medianStep(c1.depth_m), step2 = medianStep(c2.depth_m);
    const double h = std::max({step1, 2.0 * o.maxShift_m / 200.0, 1e-4});
    const double origin = std::floor(std::min(lo1, lo2 - highest) / h) * h;
    const double end = std::max(hi1, hi2 - lowest);
    const auto cells = static_cast<std::size_t>(std::ceil((end - origin) / h)) + 2;
    const double centre1 = firstReading(c1), centre2 = firstReading(c2);
    DepthCurve window1;
    for (std::size_t i = 0; i < c1.depth_m.size(); ++i)
        if (c1.depth_m[i] >= o.top_m && c1.depth_m[i] <= o.bottom_m) {
            window1.depth_m.push_back(c1.depth_m[i]);
            window1.values.push_back(c1.values[i]);
        }
    const std::vector<double> a = cellMeans(window1, origin, h, cells, 2.0 * step1 + h, centre1);
    // Curve 2 on the same grid, shifted: lag L compares cell k of curve 1 with curve 2's cell
    // k + L (the cells of curve 2 start at origin + L*h).
    const auto firstLag = static_cast<long>(std::floor(lowest / h));
    const auto lastLag = static_cast<long>(std::ceil(highest / h));
    const double origin2 = origin + static_cast<double>(firstLag) * h;
    const auto cells2 = cells + static_cast<std::size_t>(lastLag - firstLag) + 1;
    const std::vector<double> b = cellMeans(c2, origin2, h, cells2, 2.0 * step2 + h, centre2);

    // Each lag's correlation on its own (blocks of lags on the workers): the same sums in the
    // same order whatever the threads.
    const auto lags = static_cast<std::size_t>(lastLag - firstLag + 1);
    std::vector<double> r(lags), n(lags);
    constexpr std::size_t kLagsABlock = 16;
    forEachBlockInOrder((lags + kLagsABlock - 1) / kLagsABlock, o.threads,
                        [&](std::size_t block, std::size_t) {
                            for (std::size_t offset = block * kLagsABlock;
                                 offset < std::min(lags, (block + 1) * kLagsABlock); ++offset) {
                                PearsonSums sums;
                                for (std::size_t k = 0; k < cells; ++k)
                                    if (std::isfinite(a[k]) && std::isfinite(b[k + offset]))
                                        sums.add(a[k], b[k + offset]);
                                r[offset] = sums.correlation();
                                n[offset] = sums.n;
                            }
                        },
                        [](std::size_t) {});
    // A lag compared over a sliver of the overlap correlates by chance: only lags that compare
    // at least half as many cells as the best covered one compete.
    const double most = *std::max_element(n.begin(), n.end());
    if (most < 10.0)
        throw std::runtime_error("the runs do not overlap enough to match depths: at most " +
                                 std::to_string(static_cast<long>(most)) + " cells of " +
                                 std::to_string(h) + " m in common, for run 1 " +
                                 describeRange(lo1, hi1) + ", run 2 " + describeRange(lo2, hi2));
    long best = -1;
    for (std::size_t i = 0; i < r.size(); ++i)
        if (n[i] >= 0.5 * most && std::isfinite(r[i]) &&
            (best < 0 || r[i] > r[static_cast<std::size_t>(best)]))
            best = static_cast<long>(i);
    if (best < 0)
        throw std::runtime_error(
            "cannot match depths: the curve does not vary where the runs overlap (give --shift "
            "or another --match-curve)");

    const double coarse = static_cast<double>(firstLag + best) * h;
    const double lo = std::max(lowest, coarse - h), hi = std::min(highest, coarse + h);
    const auto negative = [&](double s) {
        const double value = shiftedCorrelation(c1, c2, s, o.top_m, o.bottom_m);
        return std::isfinite(value) ? -value : 2.0;
    };
    std::uintmax_t iterations = 100;
    const auto [shift, negativeR] = boost::math::tools::brent_find_minima(
        negative, lo, hi, std::numeric_limits<double>::digits / 2, iterations);
    // The grid's own optimum where the refinement found nothing better (a flat stretch).
    const double atCoarse = shiftedCorrelation(c1, c2, coarse, o.top_m, o.bottom_m);
    DepthMatch out;
    out.shift_m = std::isfinite(atCoarse) && atCoarse > -negativeR ? coarse : shift;
    out.correlation = shiftedCorrelation(c1, c2, out.shift_m, o.top_m, o.bottom_m, &out.samples);
    return out;
}

DepthMapping fitDepthMapping(const DepthCurve& c1, const DepthCurve& c2,
                             const DepthMappingOptions& o) {
    DepthMapping mapping;
    mapping.match = matchDepths(c1, c2, o.match);
    mapping.shift_m = mapping.match.shift_m;
    const auto [lo1, hi1] = readRange(c1, o.match.top_m, o.match.bottom_m);
    const auto [lo2, hi2] = readRange(c2, -1.0e300, 1.0e300);
    const double top = std::max(lo1, lo2 - mapping.shift_m);
    const double bottom = std::min(hi1, hi2 - mapping.shift_m);
    mapping.reference_m = top;
    if (!o.allowStretch || !(bottom - top >= o.minStretchInterval_m)) return mapping;

    // The two tie windows, side by side when there are threads to spare (each then correlates
    // on half of them).
    const double third = (bottom - top) / 3.0;
    const double windowTops[2] = {top, bottom - third};
    std::optional<DepthMatch> ties[2];
    forEachBlockInOrder(
        2, o.match.threads > 1 ? 2 : 1,
        [&](std::size_t k, std::size_t) {
            DepthMatchOptions tie = o.match;
            tie.centre_m = mapping.shift_m;
            tie.top_m = windowTops[k];
            tie.bottom_m = windowTops[k] + third;
            tie.threads = std::max(1, o.match.threads / 2);
            try {
                ties[k] = matchDepths(c1, c2, tie);
            } catch (const std::runtime_error&) {
                // a window without a match: no stretch
            }
        },
        [](std::size_t) {});
    for (std::size_t k = 0; k < 2; ++k) {
        if (!ties[k]) return mapping;
        mapping.ties.push_back({windowTops[k] + third / 2.0, *ties[k]});
    }
    const DepthTie& upper = mapping.ties.front();
    const DepthTie& lower = mapping.ties.back();
    if (upper.match.correlation < o.minTieCorrelation ||
        lower.match.correlation < o.minTieCorrelation ||
        !(std::abs(lower.match.shift_m - upper.match.shift_m) > o.stretchTolerance_m))
        return mapping;
    mapping.stretch = (lower.match.shift_m - upper.match.shift_m) / (lower.md1_m - upper.md1_m);
    mapping.reference_m = upper.md1_m;
    mapping.shift_m = upper.match.shift_m;
    return mapping;
}

}  // namespace caliper3d::reconstruction

#include "scenegraph/picture_scale.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "reconstruction/well_path.h"

namespace caliper3d::scenegraph {

namespace {
constexpr std::size_t kSampledRows = 4096;

// Rows [first, last) of `depth` within [top, bottom].
std::pair<std::size_t, std::size_t> rowsIn(const std::vector<double>& depth, double top,
                                           double bottom) {
    const auto first =
        static_cast<std::size_t>(std::lower_bound(depth.begin(), depth.end(), top) - depth.begin());
    const auto last = static_cast<std::size_t>(
        std::upper_bound(depth.begin(), depth.end(), bottom) - depth.begin());
    return {first, std::max(first, last)};
}

constexpr std::size_t kSampledPathPoints = 512;

// The path's centres at rows in [top, bottom], sampled to about kSampledPathPoints, the last
// row always included.
std::vector<glm::dvec3> sampledPath(const reconstruction::WellGeometry& geometry, double top,
                                    double bottom) {
    const auto [first, last] = rowsIn(geometry.table().depth_m, top, bottom);
    std::vector<glm::dvec3> points;
    if (first == last) return points;
    const std::size_t stride = std::max<std::size_t>(1, (last - first) / kSampledPathPoints);
    for (std::size_t row = first; row < last; row += stride) points.push_back(geometry.centre(row));
    if ((last - 1 - first) % stride != 0) points.push_back(geometry.centre(last - 1));
    return points;
}

// The distance between segments [p0, p1] and [q0, q1] (Ericson, Real-Time Collision
// Detection, 5.1.9: the closest points' parameters, each clamped to its segment).
double segmentDistance(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& q0,
                       const glm::dvec3& q1) {
    const glm::dvec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
    const double a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
    constexpr double kTiny = 1e-18;
    double s = 0.0, t = 0.0;
    if (a <= kTiny && e <= kTiny) return glm::length(r);
    if (a <= kTiny) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = glm::dot(d1, r);
        if (e <= kTiny) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = glm::dot(d1, d2), denom = a * e - b * b;
            s = denom > kTiny ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0.0) {
                t = 0.0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1.0) {
                t = 1.0;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    return glm::length(p0 + d1 * s - (q0 + d2 * t));
}

// The distance between two boxes (0 where they overlap): a lower bound of any two points'.
double boxDistance(const Bounds& a, const Bounds& b) {
    const glm::dvec3 gap = glm::max(glm::dvec3(0.0), glm::max(a.lo - b.hi, b.lo - a.hi));
    return glm::length(gap);
}

// Runs of kChunkSegments segments of a polyline, each with the box around its points: whole
// runs of segments farther apart than the closest approach found so far are passed over.
constexpr std::size_t kChunkSegments = 16;

struct Chunk {
    std::size_t begin, end;  // segments [begin, end): segment i runs from point i to i + 1
    Bounds box;
};

// A single point is a segment of no length.
std::size_t segmentCount(const std::vector<glm::dvec3>& p) {
    return std::max<std::size_t>(1, p.size() - 1);
}

const glm::dvec3& segmentEnd(const std::vector<glm::dvec3>& p, std::size_t i) {
    return p[std::min(i + 1, p.size() - 1)];
}

std::vector<Chunk> chunksOf(const std::vector<glm::dvec3>& p) {
    std::vector<Chunk> chunks;
    const std::size_t n = segmentCount(p);
    for (std::size_t begin = 0; begin < n; begin += kChunkSegments) {
        Chunk& chunk = chunks.emplace_back(Chunk{begin, std::min(begin + kChunkSegments, n), {}});
        for (std::size_t i = chunk.begin; i < chunk.end; ++i) chunk.box.add(p[i]);
        chunk.box.add(segmentEnd(p, chunk.end - 1));
    }
    return chunks;
}

// The closest approach of polylines `a` and `b` where it is under `limit` (some distance at
// least `limit` otherwise). A segment is never nearer than its box is, so pairs of runs, and
// then segments of `a`, whose boxes lie at least the closest approach found so far apart are
// passed over: 100 wells of 512 points each took 70 ms a field when every pair of segments of
// two neighbours was measured.
double polylineDistance(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b,
                        double limit = std::numeric_limits<double>::infinity()) {
    if (a.empty() || b.empty()) return std::numeric_limits<double>::infinity();
    const std::vector<Chunk> ca = chunksOf(a), cb = chunksOf(b);
    double best = limit;
    for (const Chunk& x : ca)
        for (const Chunk& y : cb) {
            if (boxDistance(x.box, y.box) >= best) continue;
            for (std::size_t i = x.begin; i < x.end; ++i) {
                const glm::dvec3& p1 = segmentEnd(a, i);
                Bounds segment;
                segment.add(a[i]);
                segment.add(p1);
                if (boxDistance(segment, y.box) >= best) continue;
                for (std::size_t j = y.begin; j < y.end; ++j)
                    best = std::min(best, segmentDistance(a[i], p1, b[j], segmentEnd(b, j)));
            }
        }
    return best;
}
}  // namespace

double tickSpacing_m(double visibleLength_m) {
    if (!(visibleLength_m > 0.0) || !std::isfinite(visibleLength_m)) return 1.0;
    const double least = visibleLength_m / kMaxDepthTicks;
    double decade = std::pow(10.0, std::floor(std::log10(least)));
    for (;;) {
        for (double m : {1.0, 2.0, 5.0})
            if (m * decade >= least * (1.0 - 1e-12)) return m * decade;
        decade *= 10.0;
    }
}

double roundUpToSeries(double value) {
    if (!(value > 0.0) || !std::isfinite(value)) return 1.0;
    double decade = std::pow(10.0, std::floor(std::log10(value)));
    for (;;) {
        for (double m : {1.0, 2.0, 3.0, 5.0})
            if (m * decade >= value * (1.0 - 1e-12)) return m * decade;
        decade *= 10.0;
    }
}

std::vector<double> seriesExaggerations() {
    std::vector<double> out;
    for (double f = 1.0; f <= kMaxExaggeration; f = roundUpToSeries(f * (1.0 + 1e-9)))
        out.push_back(f);
    return out;
}

double roundDownToSeries(double value) {
    if (!(value > 0.0) || !std::isfinite(value)) return 1.0;
    double decade = std::pow(10.0, std::floor(std::log10(value)));
    if (decade > value * (1.0 + 1e-12)) decade /= 10.0;  // log10 rounded up at a power of ten
    for (;;) {
        for (double m : {5.0, 3.0, 2.0, 1.0})
            if (m * decade <= value * (1.0 + 1e-12)) return m * decade;
        decade /= 10.0;
    }
}

double separatedExaggeration(double closestApproach_m, double maxRadiusA_m, double maxRadiusB_m) {
    const double radii = maxRadiusA_m + maxRadiusB_m;
    if (!(radii > 0.0)) return kMaxExaggeration;  // nothing drawn around a path
    const double most = kTubeClearance * closestApproach_m / radii;
    if (!(most >= 1.0)) return 0.0;
    return std::min(roundDownToSeries(most), kMaxExaggeration);
}

double autoExaggeration(double extent_m, double typicalRadius_m, int pictureHeight_px) {
    if (!(extent_m > 0.0) || !(typicalRadius_m > 0.0) || pictureHeight_px <= 0) return 1.0;
    const double fraction =
        std::max(kMinDrawnDiameter, kMinDrawnDiameter_px / static_cast<double>(pictureHeight_px));
    const double wanted = fraction * extent_m / (2.0 * typicalRadius_m);
    if (wanted <= 1.0) return 1.0;
    return std::min(roundUpToSeries(wanted), kMaxExaggeration);
}

double chooseExaggeration(
    const std::vector<std::shared_ptr<const reconstruction::WellGeometry>>& wells, double top_m,
    double bottom_m, int pictureHeight_px) {
    Bounds bounds;
    double radius = std::numeric_limits<double>::infinity();
    for (const auto& well : wells) {
        const std::vector<double>& depth = well->table().depth_m;
        if (depth.empty()) continue;
        const double top = std::max(top_m, depth.front());  // the log, not the path above it
        addPathBounds(*well, top, bottom_m, bounds);
        const double r = typicalRadius_m(*well, top, bottom_m);
        if (std::isfinite(r)) radius = std::min(radius, r);  // the thinnest hole reads too
    }
    double factor = autoExaggeration(bounds.diagonal(), radius, pictureHeight_px);
    if (wells.size() < 2 || factor <= 1.0) return factor;

    // A field: no two tubes touch (kTubeClearance).
    struct Drawn {
        std::vector<glm::dvec3> path;
        Bounds box;
        double maxRadius_m;
    };
    std::vector<Drawn> drawn;
    for (const auto& well : wells) {
        const std::vector<double>& depth = well->table().depth_m;
        if (depth.empty()) continue;
        const double top = std::max(top_m, depth.front());
        const double r = maxRadius_m(*well, top, bottom_m);
        if (!std::isfinite(r)) continue;  // no tube drawn
        Drawn& d = drawn.emplace_back(Drawn{sampledPath(*well, top, bottom_m), {}, r});
        for (const glm::dvec3& p : d.path) d.box.add(p);
    }
    for (std::size_t i = 0; i < drawn.size(); ++i)
        for (std::size_t j = i + 1; j < drawn.size(); ++j) {
            const double radii = drawn[i].maxRadius_m + drawn[j].maxRadius_m;
            // Paths this far apart allow the factor already: no need to look closer.
            const double enough = factor * radii / kTubeClearance;
            if (boxDistance(drawn[i].box, drawn[j].box) >= enough) continue;
            const double most =
                separatedExaggeration(polylineDistance(drawn[i].path, drawn[j].path, enough),
                                      drawn[i].maxRadius_m, drawn[j].maxRadius_m);
            if (most >= 1.0) factor = std::min(factor, most);
        }
    return factor;
}

void Bounds::add(const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
}

double Bounds::diagonal() const {
    return empty() ? 0.0 : glm::length(hi - lo);
}

void addPathBounds(const reconstruction::WellGeometry& geometry, double top_m, double bottom_m,
                   Bounds& bounds) {
    const std::vector<double>& depth = geometry.table().depth_m;
    if (depth.empty()) return;
    if (top_m < depth.front()) {
        // The path from the wellhead down to the first row (an arc: its ends and middle bound it
        // closely enough for a scale).
        const double first = depth.front();
        for (double md : {std::max(top_m, 0.0), 0.5 * (std::max(top_m, 0.0) + first)})
            bounds.add(reconstruction::pathAt(geometry, md).position);
    }
    const auto [first, last] = rowsIn(depth, top_m, bottom_m);
    if (first == last) return;
    const std::size_t stride = std::max<std::size_t>(1, (last - first) / kSampledRows);
    for (std::size_t row = first; row < last; row += stride) bounds.add(geometry.centre(row));
    bounds.add(geometry.centre(last - 1));
}

double typicalRadius_m(const reconstruction::WellGeometry& geometry, double top_m,
                       double bottom_m) {
    const io::SectionTable& table = geometry.table();
    const auto [first, last] = rowsIn(table.depth_m, top_m, bottom_m);
    const std::size_t stride = std::max<std::size_t>(1, (last - first) / kSampledRows);
    std::vector<double> radii;
    radii.reserve(((last - first) / stride + 1) * static_cast<std::size_t>(table.armCount));
    for (std::size_t row = first; row < last; row += stride) {
        if (!geometry.measured(row)) continue;
        const double* r = table.radii(row);
        for (int arm = 0; arm < table.armCount; ++arm)
            if (std::isfinite(r[arm]) && r[arm] > 0.0) radii.push_back(r[arm]);
    }
    if (radii.empty()) return std::nan("");
    const auto middle = radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 2);
    std::nth_element(radii.begin(), middle, radii.end());
    return *middle / 1000.0;
}

double maxRadius_m(const reconstruction::WellGeometry& geometry, double top_m, double bottom_m) {
    const io::SectionTable& table = geometry.table();
    const auto [first, last] = rowsIn(table.depth_m, top_m, bottom_m);
    double most = std::nan("");
    for (std::size_t row = first; row < last; ++row) {
        if (!geometry.measured(row)) continue;
        const double* r = table.radii(row);
        for (int arm = 0; arm < table.armCount; ++arm)
            if (std::isfinite(r[arm]) && r[arm] > 0.0 && !(r[arm] <= most)) most = r[arm];
    }
    return most / 1000.0;
}

double closestApproach_m(const reconstruction::WellGeometry& a,
                         const reconstruction::WellGeometry& b, double top_m, double bottom_m) {
    return polylineDistance(sampledPath(a, top_m, bottom_m), sampledPath(b, top_m, bottom_m));
}

}  // namespace caliper3d::scenegraph

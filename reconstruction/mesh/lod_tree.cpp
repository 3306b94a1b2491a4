#include "reconstruction/mesh/lod_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <thread>

#include <glm/geometric.hpp>

#include "reconstruction/mesh/swing_door.h"
#include "reconstruction/section/section_frame.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

int lodTreeDepth(std::size_t segments) {
    int depth = 1;
    std::size_t covered = kLodTreeFanOut;
    while (covered < segments) {
        covered *= kLodTreeFanOut;
        ++depth;
    }
    return depth;
}

namespace {

std::size_t spanSize(int depth) {
    std::size_t size = 1;
    for (int d = 0; d < depth; ++d) size *= kLodTreeFanOut;
    return size;
}

// How much the full ring can move when its pads move: the largest sum of the absolute
// weights of one sample (the sampler's infinity norm, its Lebesgue constant; about 1.55 for
// six pads and 48 samples). Pads within e of a line give samples within this times e.
double samplerNorm(const PeriodicSplineSampler& sampler) {
    double worst = 0.0;
    const auto knots = static_cast<std::size_t>(sampler.knots());
    for (std::size_t j = 0; j < static_cast<std::size_t>(sampler.samples()); ++j) {
        double sum = 0.0;
        for (std::size_t k = 0; k < knots; ++k) sum += std::abs(sampler.weights()[j * knots + k]);
        worst = std::max(worst, sum);
    }
    return worst;
}

// What a span hands to the span above it besides its mesh.
struct SpanRows {
    std::vector<std::size_t> rows;  // kept, increasing
    double error_mm = 0.0;          // of the pads' polygons, drawn (exaggeration included)
    double ringError_mm = 0.0;      // of the level's rings against the full spline, drawn
    double pathDeviation_m = 0.0;   // the straight path between kept rows from the true path,
                                    //   or the tool's turn between them, drawn
    double maxRadius_mm = 0.0;      // largest knot value, undrawn
};

// The largest drawn distance (mm) between a measured candidate's pad polygon and the straight
// line (in depth) between the polygons of the kept rows on either side of it, each polygon
// drawn about its own centroid as buildRingMesh draws it.
double keptDeviation_mm(const WellGeometry& g, const std::vector<std::size_t>& candidates,
                        const std::vector<double>& values, std::size_t knots,
                        const std::vector<std::size_t>& kept) {
    const std::vector<double>& depth = g.table().depth_m;
    const double exaggeration = g.options().radialExaggeration;
    std::vector<double> pads(knots);
    auto ring = [&](std::size_t c, std::vector<glm::dvec2>& out) {
        std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(c * knots), knots, pads.begin());
        drawnRing(pads, exaggeration, out);
    };
    std::vector<glm::dvec2> from, to, here;
    double worst = 0.0;
    std::size_t a = 0;  // the candidate that is kept[k]; every kept row is a candidate
    for (std::size_t k = 0; k + 1 < kept.size(); ++k) {
        while (candidates[a] < kept[k]) ++a;
        std::size_t b = a;
        while (candidates[b] < kept[k + 1]) ++b;
        if (b > a + 1 && g.measured(kept[k]) && g.measured(kept[k + 1])) {
            ring(a, from);
            ring(b, to);
            const double length = depth[kept[k + 1]] - depth[kept[k]];
            for (std::size_t c = a + 1; c < b; ++c) {
                if (!g.measured(candidates[c])) continue;
                ring(c, here);
                const double t =
                    length > 0.0 ? (depth[candidates[c]] - depth[kept[k]]) / length : 0.0;
                for (std::size_t j = 0; j < knots; ++j)
                    worst =
                        std::max(worst, glm::length(here[j] - (from[j] + t * (to[j] - from[j]))));
            }
        }
        a = b;
    }
    return worst;
}

double distanceToChord(const Ned& p, const Ned& a, const Ned& b) {
    const Ned ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

struct Built {
    SpanMesh mesh;
    SpanRows rows;
};

// The ring and path parts of a span's error (see buildSpan), into `result`.
void measureRingsAndPath(const WellGeometry& g, const std::vector<std::size_t>& candidates,
                         const LodLevel& level, double childRingError_mm, double childDeviation_m,
                         SpanRows& result) {
    const auto knots = static_cast<std::size_t>(g.knotCount());
    // The ring each kept row draws (the pads' polygon, or fewer spline points) against its
    // full spline, measured on the kept rows; between them the rings are close to the
    // straight line between theirs (the spline is linear in the pads).
    {
        std::optional<PeriodicSplineSampler> sampler;
        if (level.points > 0) sampler.emplace(static_cast<int>(knots), level.points);
        for (std::size_t r : result.rows)
            result.ringError_mm =
                std::max(result.ringError_mm, ringError_mm(g, r, sampler ? &*sampler : nullptr));
        result.ringError_mm = std::max(result.ringError_mm, childRingError_mm);
    }

    // How far the straight path between kept rows strays from the candidates' centres.
    double deviation_m = 0.0;
    std::size_t k = 0;
    for (const std::size_t candidate : candidates) {
        while (k + 1 < result.rows.size() && result.rows[k + 1] < candidate) ++k;
        if (k + 1 >= result.rows.size()) break;
        deviation_m =
            std::max(deviation_m, distanceToChord(g.centre(candidate), g.centre(result.rows[k]),
                                                  g.centre(result.rows[k + 1])));
    }
    // The tool turns between kept rows: a straight edge from a pad's point at one kept row to
    // the same pad's point at the next cuts inside the wall between them, by up to
    // r (1 - cos(turn / 2)) at the middle for a drawn radius r.
    const double drawnRadius_m =
        result.maxRadius_mm * std::max(1.0, 2.0 * g.options().radialExaggeration - 1.0) / 1000.0;
    for (std::size_t i = 0; i + 1 < result.rows.size(); ++i) {
        const std::size_t r0 = result.rows[i], r1 = result.rows[i + 1];
        if (!g.measured(r0) || !g.measured(r1)) continue;
        const double cosTurn = std::clamp(glm::dot(g.frame(r0).arm1, g.frame(r1).arm1), -1.0, 1.0);
        const double turn = std::acos(cosTurn);
        deviation_m = std::max(deviation_m, drawnRadius_m * (1.0 - std::cos(turn / 2.0)));
    }
    result.pathDeviation_m = deviation_m + childDeviation_m;
}

Built buildSpan(const WellGeometry& g, int depth, std::size_t index,
                const std::vector<SpanRows>& children) {
    const std::size_t segments = g.segmentCount();
    const auto [s0, s1] = spanSegments(depth, index, segments);
    const std::size_t first = g.segmentRows(s0).first, last = g.segmentRows(s1).second;
    const auto knots = static_cast<std::size_t>(g.knotCount());
    Built out;
    SpanRows& result = out.rows;

    // The rows to choose from: every measured row at depth 1, else the rows the children kept.
    std::vector<std::size_t> candidates;
    double childError_mm = 0.0, childDeviation_m = 0.0, childRingError_mm = 0.0;
    if (depth == 1) {
        candidates.reserve(last - first + 1);
        for (std::size_t r = first; r <= last; ++r)
            if (r == first || r == last || g.measured(r)) candidates.push_back(r);
    } else {
        const std::size_t from = index * kLodTreeFanOut;
        const std::size_t to = std::min(from + kLodTreeFanOut, children.size());
        for (std::size_t c = from; c < to; ++c) {
            const SpanRows& child = children[c];
            for (std::size_t r : child.rows)
                if (candidates.empty() || r > candidates.back()) candidates.push_back(r);
            childError_mm = std::max(childError_mm, child.error_mm);
            childRingError_mm = std::max(childRingError_mm, child.ringError_mm);
            childDeviation_m = std::max(childDeviation_m, child.pathDeviation_m);
            result.maxRadius_mm = std::max(result.maxRadius_mm, child.maxRadius_mm);
        }
    }
    std::vector<double> values(candidates.size() * knots, 0.0);
    for (std::size_t c = 0; c < candidates.size(); ++c)
        if (g.measured(candidates[c])) {
            g.sectionKnots(candidates[c], values.data() + c * knots);
            if (depth == 1)
                for (std::size_t k = 0; k < knots; ++k)
                    result.maxRadius_mm = std::max(result.maxRadius_mm, values[c * knots + k]);
        }

    const LodLevel level = spanLevel(g.options(), static_cast<int>(knots), depth);
    result.rows = swingDoor(
        g, candidates.size(), [&candidates](std::size_t c) { return candidates[c]; },
        [&values, knots](std::size_t c, std::size_t k) { return values[c * knots + k]; }, knots,
        level);
    // The error is measured, not the tolerance assumed: the kept rows' straight lines differ
    // from the candidates' by at most `level.tolerance_mm` (times the exaggeration), and
    // mostly far less on a smooth wall. Both the children's polygons and this span's are
    // piecewise linear in depth with breaks at the candidates (this span keeps a subset of
    // them), so their largest difference lies on a candidate; adding the children's error
    // bounds the distance to every measured row's polygon (the triangle inequality).
    result.error_mm = keptDeviation_mm(g, candidates, values, knots, result.rows) + childError_mm;
    measureRingsAndPath(g, candidates, level, childRingError_mm, childDeviation_m, result);

    SpanMesh& mesh = out.mesh;
    mesh.depth = depth;
    mesh.index = index;
    mesh.firstSegment = s0;
    mesh.lastSegment = s1;
    mesh.firstRow = first;
    mesh.lastRow = last;
    const double exaggeration = g.options().radialExaggeration;
    // As for a segment (lod_levels.cpp): a drawn point lies within F r + (F - 1) r of the path.
    mesh.maxRadius_m =
        static_cast<float>(result.maxRadius_mm * std::max(1.0, 2.0 * exaggeration - 1.0) / 1000.0);
    // A full ring is the spline through its pads: pads within e of a line give a spline
    // within samplerNorm e of the line's spline, so the pads' error counts that much.
    mesh.error_mm = static_cast<float>(samplerNorm(g.sampler()) * result.error_mm +
                                       result.ringError_mm + result.pathDeviation_m * 1000.0);
    mesh.mesh = buildRingMesh(g, result.rows, level.points);

    const glm::dvec3 a = toScene(g.centre(first)), b = toScene(g.centre(last));
    const glm::dvec3 centre = (a + b) / 2.0;
    double reach = glm::length(b - a) / 2.0;
    for (std::size_t r : candidates)
        reach = std::max(reach, glm::length(toScene(g.centre(r)) - centre));
    mesh.centre = glm::vec3(centre);
    mesh.radius = static_cast<float>(reach + childDeviation_m) + mesh.maxRadius_m;
    return out;
}

}  // namespace

std::size_t spanCount(int depth, std::size_t segments) {
    const std::size_t size = spanSize(depth);
    return (segments + size - 1) / size;
}

std::pair<std::size_t, std::size_t> spanSegments(int depth, std::size_t index,
                                                 std::size_t segments) {
    const std::size_t size = spanSize(depth);
    const std::size_t first = index * size;
    return {first, std::min(first + size, segments) - 1};
}

LodLevel spanLevel(const GeometryOptions& options, int knots, int depth) {
    const LodLevel coarsest = lodPyramid(options).back();
    LodLevel level;
    level.tolerance_mm = coarsest.tolerance_mm * std::pow(2.0, depth);
    level.maxSpacing_m =
        std::max(coarsest.maxSpacing_m, options.segmentLength_m) * std::pow(4.0, depth);
    level.points = knots <= 8 ? 0 : std::max(6, knots >> depth);
    return level;
}

std::vector<SpanMesh> buildSpanMeshes(const WellGeometry& geometry,
                                      const std::atomic<bool>* cancel) {
    std::vector<SpanMesh> out;
    const std::size_t segments = geometry.segmentCount();
    if (segments == 0) return out;
    const int depth = lodTreeDepth(segments);
    std::vector<SpanRows> children;
    for (int d = 1; d <= depth; ++d) {
        const std::size_t count = spanCount(d, segments);
        std::vector<Built> built(count);
        // The spans of one depth are independent: two threads (the machine's two cores).
        auto build = [&](std::size_t from) {
            for (std::size_t i = from; i < count; i += 2) {
                if (cancel && cancel->load()) return;
                built[i] = buildSpan(geometry, d, i, children);
            }
        };
        if (count > 1) {
            std::thread helper(build, 1);
            build(0);
            helper.join();
        } else {
            build(0);
        }
        if (cancel && cancel->load()) return out;
        children.clear();
        children.reserve(count);
        for (Built& b : built) {
            children.push_back(std::move(b.rows));
            out.push_back(std::move(b.mesh));
        }
    }
    return out;
}

CoarseMeshes buildCoarseMeshes(const WellGeometry& geometry, int firstLevel) {
    CoarseMeshes out;
    const std::size_t count = geometry.segmentCount();
    out.segments.resize(count);
    auto build = [&geometry, &out, count, firstLevel](std::size_t from) {
        for (std::size_t s = from; s < count; s += 2)
            out.segments[s] = buildCoarseSegment(geometry, s, firstLevel);
    };
    std::thread helper(build, 1);
    build(0);
    helper.join();
    out.spans = buildSpanMeshes(geometry);
    return out;
}

}  // namespace caliper3d::reconstruction

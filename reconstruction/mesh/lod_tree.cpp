#include "reconstruction/mesh/lod_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <thread>

#include <glm/geometric.hpp>

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

// What a span hands to the span above it besides its mesh.
struct SpanRows {
    std::vector<std::size_t> rows;  // kept, increasing
    double error_mm = 0.0;          // of the radii, undrawn (no exaggeration, no chord error)
    double pathDeviation_m = 0.0;   // the straight path between kept rows from the true path
    double maxRadius_mm = 0.0;      // largest knot value, undrawn
};

bool mustKeep(const WellGeometry& g, std::size_t row) {
    const std::size_t rows = g.table().rowCount();
    return !g.measured(row) || (row > 0 && !g.measured(row - 1)) ||
           (row + 1 < rows && !g.measured(row + 1));
}

// The swing-door decimation of lod_levels.cpp over a subset of rows: `candidates`
// (increasing, both span ends first and last) with their knots in `values`; a candidate
// is left out while the straight line (in depth) between the kept candidates on either side
// stays within `level.tolerance_mm` of every one of its knots.
std::vector<std::size_t> swingDoor(const WellGeometry& g,
                                   const std::vector<std::size_t>& candidates,
                                   const std::vector<double>& values, std::size_t knots,
                                   const LodLevel& level) {
    std::vector<std::size_t> kept;
    if (candidates.empty()) return kept;
    const std::vector<double>& depth = g.table().depth_m;
    const std::size_t last = candidates.size() - 1;
    auto value = [&](std::size_t c, std::size_t k) { return values[c * knots + k]; };
    std::vector<double> lo(knots), hi(knots);
    kept.push_back(candidates[0]);
    std::size_t anchor = 0;
    while (anchor < last) {
        std::fill(lo.begin(), lo.end(), -std::numeric_limits<double>::infinity());
        std::fill(hi.begin(), hi.end(), std::numeric_limits<double>::infinity());
        std::size_t best = anchor + 1;
        const bool anchorMeasured = g.measured(candidates[anchor]);
        for (std::size_t c = anchor + 1; c <= last; ++c) {
            const double dd = depth[candidates[c]] - depth[candidates[anchor]];
            if (dd > level.maxSpacing_m && c > anchor + 1) break;
            if (!anchorMeasured || !(dd > 0.0)) {
                best = c;
                break;
            }
            // c may end the run when the straight line to it stays inside every corridor.
            bool fits = true;
            for (std::size_t k = 0; k < knots && fits; ++k) {
                const double slope = (value(c, k) - value(anchor, k)) / dd;
                fits = slope >= lo[k] && slope <= hi[k];
            }
            if (!fits) break;
            best = c;
            // A span end or a gap's edge ends the run (kept at every depth).
            if (c == last || mustKeep(g, candidates[c])) break;
            bool open = true;
            for (std::size_t k = 0; k < knots; ++k) {
                lo[k] = std::max(lo[k], (value(c, k) - level.tolerance_mm - value(anchor, k)) / dd);
                hi[k] = std::min(hi[k], (value(c, k) + level.tolerance_mm - value(anchor, k)) / dd);
                open = open && lo[k] <= hi[k];
            }
            if (!open) break;
        }
        kept.push_back(candidates[best]);
        anchor = best;
    }
    return kept;
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
    double childError_mm = 0.0, childDeviation_m = 0.0;
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
    result.rows = swingDoor(g, candidates, values, knots, level);
    result.error_mm = level.tolerance_mm + childError_mm;

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
    result.pathDeviation_m = deviation_m + childDeviation_m;

    SpanMesh& mesh = out.mesh;
    mesh.depth = depth;
    mesh.index = index;
    mesh.firstSegment = s0;
    mesh.lastSegment = s1;
    mesh.firstRow = first;
    mesh.lastRow = last;
    const double exaggeration = g.options().radialExaggeration;
    const double drawn_mm = result.maxRadius_mm * exaggeration;
    // As for a segment (lod_levels.cpp): a drawn point lies within F r + (F - 1) r of the path.
    mesh.maxRadius_m =
        static_cast<float>(result.maxRadius_mm * std::max(1.0, 2.0 * exaggeration - 1.0) / 1000.0);
    mesh.error_mm = static_cast<float>(
        result.error_mm * exaggeration +
        chordError(drawn_mm, level.points > 0 ? level.points : static_cast<int>(knots)) +
        result.pathDeviation_m * 1000.0);
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

}  // namespace caliper3d::reconstruction

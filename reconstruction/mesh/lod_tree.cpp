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

// The children [from, to) of span `index` among the `children` spans of the depth below.
std::pair<std::size_t, std::size_t> childSpans(std::size_t index, std::size_t children) {
    const std::size_t from = index * kLodTreeFanOut;
    return {from, std::min(from + kLodTreeFanOut, children)};
}

// Which rows can raise the worst distance at some exaggeration F_f (padDeviations). A row
// whose polygon lies within p of the line's centroid and q of its shape (p = |dc|, q the largest
// |ds|) is drawn within p + F q at F, so it cannot raise the worst w_f at any F_f where
// p + F_f q <= s_f, s_f the root of w_f narrowed by far more than rounding can take. That holds
// at every F_f where p <= h(q), h the lower envelope of the lines s_f - F_f q: a few pieces,
// walked in order of q, rebuilt only when a worst rises. (Before, each row tested every F_f:
// with the fourteen factors a field's well is planned for, a fifth of its plan.) Written here:
// no library has the envelope of a handful of lines.
class PassOver {
public:
    explicit PassOver(const std::vector<double>& fs) : m_fs(fs), m_roots(fs.size(), 0.0) {
        rebuild();
    }

    // The worst squared distances changed: the envelope from them.
    void update(const std::vector<double>& worst2) {
        for (std::size_t f = 0; f < m_fs.size(); ++f)
            m_roots[f] = std::sqrt(worst2[f] / (1.0 + 1e-8));
        rebuild();
    }

    // True where a row within p of the centroid's line and q of the shape's may raise a worst.
    bool mayRaise(double p, double q) const {
        std::size_t piece = 0;
        while (piece + 1 < m_from.size() && m_from[piece + 1] <= q) ++piece;
        const std::size_t f = m_line[piece];
        return p > m_roots[f] - m_fs[f] * q;
    }

private:
    // From q = 0, the line lowest there (the steeper of equals); then, at each step, the
    // steeper line that crosses the current one first.
    void rebuild() {
        m_from.clear();
        m_line.clear();
        if (m_fs.empty()) return;
        std::size_t current = 0;
        for (std::size_t f = 1; f < m_fs.size(); ++f)
            if (m_roots[f] < m_roots[current] ||
                (m_roots[f] == m_roots[current] && m_fs[f] > m_fs[current]))
                current = f;
        double from = 0.0;
        for (;;) {
            m_from.push_back(from);
            m_line.push_back(current);
            std::size_t next = current;
            double at = std::numeric_limits<double>::infinity();
            for (std::size_t f = 0; f < m_fs.size(); ++f) {
                if (!(m_fs[f] > m_fs[current])) continue;
                const double cross = (m_roots[f] - m_roots[current]) / (m_fs[f] - m_fs[current]);
                if (cross < at || (cross == at && m_fs[f] > m_fs[next])) {
                    at = cross;
                    next = f;
                }
            }
            if (next == current) return;
            from = std::max(from, at);
            current = next;
        }
    }

    const std::vector<double>& m_fs;
    std::vector<double> m_roots;      // s_f
    std::vector<double> m_from;       // where each piece starts, in q
    std::vector<std::size_t> m_line;  // the factor whose line each piece is
};

// The pads' part of a span's error at each exaggeration `fs` (SpanPlan::padError_mm): the
// largest drawn distance between a measured candidate's pad polygon and the straight line (in
// depth) between the polygons of the kept rows on either side of it, each polygon drawn about
// its own centroid as buildRingMesh draws it. Drawn F times larger about its centroid c, a
// polygon's point p is c + F (p - c), so a distance is |dc + F ds|: dc between the centroids
// and ds between the points about them. Both are taken once per point; each F costs a few
// multiplications. Also the largest |dc| and |ds| (SpanPlan::padCentroid_mm, padShape_mm).
// `knotsOf(c)`: candidate c's knots.
//
// Written from the radii, not from the polygons' points (drawnRing, ringCentroid): the points
// lie at the radii along the same unit vectors u_j for every row, so with d_j the radius' own
// difference from the straight line, ds_j = d_j u_j - dc, and the centroid (the shoelace's, each
// cross product r_j r_j+1 times the same sine) is the sum of r_j (m_j-1 + m_j) u_j over three
// times the sum of m_j, m_j = r_j r_j+1. With the knots taken once (planCoarseMeshes), a
// field's well is planned in 35-36 ms against 43-44 (docs/benchmarks.md, "Plans from the
// radii").
template <class KnotsOf>
void padDeviations(const WellGeometry& g, const std::vector<std::size_t>& candidates,
                   KnotsOf knotsOf, std::size_t knots, const std::vector<std::size_t>& kept,
                   const std::vector<double>& fs, SpanPlan& plan) {
    const std::vector<double>& depth = g.table().depth_m;
    const std::vector<glm::dvec2>& unit = unitRing(knots);
    // The cross product of consecutive unit vectors: the same for every pair.
    const double turn = knots > 1 ? unit[0].x * unit[1].y - unit[1].x * unit[0].y : 0.0;
    // A candidate's centroid as ringCentroid takes it of drawnRing(radii, 1): the tool axis
    // where the polygon has no area.
    auto centroid = [&](const double* r) {
        double area = 0.0;
        glm::dvec2 sum(0.0);
        double before = r[knots - 1] * r[0];  // m_j-1 for j = 0
        for (std::size_t j = 0; j < knots; ++j) {
            const double m = r[j] * r[j + 1 == knots ? 0 : j + 1];
            area += m;
            sum += (r[j] * (before + m)) * unit[j];
            before = m;
        }
        const double area2 = area * turn;
        return std::abs(area2) > 1e-6 ? sum * (1.0 / (3.0 * area)) : glm::dvec2(0.0);
    };
    std::vector<double> worst2(fs.size(), 0.0);
    PassOver passOver(fs);
    double worstCentroid2 = 0.0, worstShape2 = 0.0;  // squared: one square root in all
    std::vector<double> along(knots);                // d_j: the radius less the straight line's
    std::size_t a = 0;  // the candidate that is kept[k]; every kept row is one
    for (std::size_t k = 0; k + 1 < kept.size(); ++k) {
        while (candidates[a] < kept[k]) ++a;
        std::size_t b = a;
        while (candidates[b] < kept[k + 1]) ++b;
        if (b > a + 1 && g.measured(kept[k]) && g.measured(kept[k + 1])) {
            const double* from = knotsOf(a);
            const double* to = knotsOf(b);
            const glm::dvec2 fromCentroid = centroid(from), toCentroid = centroid(to);
            const double length = depth[kept[k + 1]] - depth[kept[k]];
            for (std::size_t c = a + 1; c < b; ++c) {
                if (!g.measured(candidates[c])) continue;
                const double* here = knotsOf(c);
                const double t =
                    length > 0.0 ? (depth[candidates[c]] - depth[kept[k]]) / length : 0.0;
                const glm::dvec2 dc =
                    centroid(here) - (fromCentroid + t * (toCentroid - fromCentroid));
                const double cc = glm::dot(dc, dc);
                worstCentroid2 = std::max(worstCentroid2, cc);
                double shape2 = 0.0;
                for (std::size_t j = 0; j < knots; ++j) {
                    along[j] = here[j] - (from[j] + t * (to[j] - from[j]));
                    // |d_j u_j - dc|^2, u_j a unit vector
                    shape2 =
                        std::max(shape2, along[j] * (along[j] - 2.0 * glm::dot(unit[j], dc)) + cc);
                }
                shape2 = std::max(shape2, 0.0);
                worstShape2 = std::max(worstShape2, shape2);
                // Each point is within |dc| + F |ds| at F: a row that cannot raise the worst
                // found at any F is passed over (most rows, once a few are in; PassOver). The
                // worst at one F is the same whichever other factors are listed.
                if (!passOver.mayRaise(std::sqrt(cc), std::sqrt(shape2))) continue;
                bool raised = false;
                for (std::size_t j = 0; j < knots; ++j) {
                    const glm::dvec2 ds = along[j] * unit[j] - dc;
                    const double cs = glm::dot(dc, ds), ss = glm::dot(ds, ds);
                    for (std::size_t f = 0; f < fs.size(); ++f) {
                        const double d2 = cc + fs[f] * (2.0 * cs + fs[f] * ss);
                        raised |= d2 > worst2[f];
                        worst2[f] = std::max(worst2[f], d2);
                    }
                }
                if (raised) passOver.update(worst2);
            }
        }
        a = b;
    }
    plan.padError_mm.resize(fs.size());
    for (std::size_t f = 0; f < fs.size(); ++f) plan.padError_mm[f] = std::sqrt(worst2[f]);
    plan.padCentroid_mm = std::sqrt(worstCentroid2);
    plan.padShape_mm = std::sqrt(worstShape2);
}

// The squared distance from `p` to the chord from `a` to `b`.
double distanceToChord2(const Ned& p, const Ned& a, const Ned& b) {
    const Ned ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    const Ned d = p - (a + t * ab);
    return glm::dot(d, d);
}

// How far the straight path between `plan`'s kept rows strays from the candidates' centres
// (SpanPlan::centreDeviation_m), and how far the candidates reach from the span's middle
// (SpanPlan::reach_m).
void pathDeviation(const WellGeometry& g, const std::vector<std::size_t>& candidates,
                   SpanPlan& plan) {
    const std::size_t first = plan.firstRow, last = plan.lastRow;
    // Each centre taken once, each distance squared (the square root of the largest is the
    // largest square root).
    const glm::dvec3 a = toScene(g.centre(first)), b = toScene(g.centre(last));
    const glm::dvec3 middle = (a + b) / 2.0;
    double reach2 = glm::dot(b - a, b - a) / 4.0, deviation2 = 0.0;
    const std::size_t kept = plan.rows.size();
    std::size_t k = 0;  // the chord from kept row k to k + 1
    Ned from(0.0), to(0.0);
    if (kept >= 2) {
        from = g.centre(plan.rows[0]);
        to = g.centre(plan.rows[1]);
    }
    for (const std::size_t candidate : candidates) {
        const Ned c = g.centre(candidate);
        const glm::dvec3 out = toScene(c) - middle;
        reach2 = std::max(reach2, glm::dot(out, out));
        while (k + 1 < kept && plan.rows[k + 1] < candidate) {
            if (++k + 1 < kept) {
                from = to;
                to = g.centre(plan.rows[k + 1]);
            }
        }
        if (k + 1 < kept) deviation2 = std::max(deviation2, distanceToChord2(c, from, to));
    }
    plan.reach_m = std::sqrt(reach2);
    plan.centreDeviation_m = std::sqrt(deviation2);
}

// The knots of every row of [first, last], row after row, at `out` (zeros for a row without
// data, never read).
void rowKnots(const WellGeometry& g, std::size_t first, std::size_t last, double* out) {
    const auto knots = static_cast<std::size_t>(g.knotCount());
    for (std::size_t r = first; r <= last; ++r) {
        double* at = out + (r - first) * knots;
        if (g.measured(r))
            g.sectionKnots(r, at);
        else
            std::fill(at, at + knots, 0.0);
    }
}

// What a span decides on the whole well (SpanPlan), from its children's plans at depth > 1.
// At depth 1, `spanKnots` may hold the knots of the span's rows (rowKnots), computed once for
// its segments' plans and its own.
SpanPlan planSpan(const WellGeometry& g, int depth, std::size_t index,
                  const std::vector<SpanPlan>& children, const std::vector<double>& fs,
                  const double* spanKnots = nullptr) {
    const std::size_t segments = g.segmentCount();
    const auto [s0, s1] = spanSegments(depth, index, segments);
    const std::size_t first = g.segmentRows(s0).first, last = g.segmentRows(s1).second;
    const auto knots = static_cast<std::size_t>(g.knotCount());
    SpanPlan plan;
    plan.depth = depth;
    plan.index = index;
    plan.firstSegment = s0;
    plan.lastSegment = s1;
    plan.firstRow = first;
    plan.lastRow = last;

    // The rows to choose from: every measured row at depth 1, else the rows the children kept.
    std::vector<std::size_t> candidates;
    std::vector<double> childPad(fs.size(), 0.0);
    double childCentroid = 0.0, childShape = 0.0;
    // A buffer of the thread's, not a fresh one cleared for each span.
    thread_local std::vector<double> scratch;
    if (depth == 1) {
        candidates.reserve(last - first + 1);
        for (std::size_t r = first; r <= last; ++r)
            if (r == first || r == last || g.measured(r)) candidates.push_back(r);
        if (!spanKnots) {
            if (scratch.size() < (last - first + 1) * knots)
                scratch.resize((last - first + 1) * knots);
            rowKnots(g, first, last, scratch.data());
            spanKnots = scratch.data();
        }
        double largest = 0.0;  // (not plan.maxRadius_mm: stored at every knot)
        for (std::size_t r = first; r <= last; ++r)
            if (g.measured(r))
                for (std::size_t k = 0; k < knots; ++k)
                    largest = std::max(largest, spanKnots[(r - first) * knots + k]);
        plan.maxRadius_mm = largest;
    } else {
        const auto [from, to] = childSpans(index, children.size());
        for (std::size_t c = from; c < to; ++c) {
            const SpanPlan& child = children[c];
            for (std::size_t r : child.rows)
                if (candidates.empty() || r > candidates.back()) candidates.push_back(r);
            for (std::size_t f = 0; f < fs.size(); ++f)
                childPad[f] = std::max(childPad[f], child.padError_mm[f]);
            childCentroid = std::max(childCentroid, child.padCentroid_mm);
            childShape = std::max(childShape, child.padShape_mm);
            plan.maxRadius_mm = std::max(plan.maxRadius_mm, child.maxRadius_mm);
        }
        // The candidates' knots, measured rows only (nothing reads an unmeasured row's).
        if (scratch.size() < candidates.size() * knots) scratch.resize(candidates.size() * knots);
        for (std::size_t c = 0; c < candidates.size(); ++c)
            if (g.measured(candidates[c]))
                g.sectionKnots(candidates[c], scratch.data() + c * knots);
    }
    // Candidate c's knots: by row at depth 1, in candidate order above.
    const double* const values = depth == 1 ? spanKnots : scratch.data();
    const std::size_t offset = depth == 1 ? first : 0;
    const bool byRow = depth == 1;
    auto knotsOf = [&candidates, values, offset, byRow, knots](std::size_t c) {
        return values + ((byRow ? candidates[c] - offset : c) * knots);
    };

    const LodLevel level = spanLevel(g.options(), static_cast<int>(knots), depth);
    plan.rows = swingDoor(
        g, candidates.size(), [&candidates](std::size_t c) { return candidates[c]; },
        [&knotsOf](std::size_t c, std::size_t k) { return knotsOf(c)[k]; }, knots, level);
    // The error is measured, not the tolerance assumed: the kept rows' straight lines differ
    // from the candidates' by at most `level.tolerance_mm` (times the exaggeration), and
    // mostly far less on a smooth wall. Both the children's polygons and this span's are
    // piecewise linear in depth with breaks at the candidates (this span keeps a subset of
    // them), so their largest difference lies on a candidate; adding the children's error
    // bounds the distance to every measured row's polygon (the triangle inequality).
    padDeviations(g, candidates, knotsOf, knots, plan.rows, fs, plan);
    for (std::size_t f = 0; f < fs.size(); ++f) plan.padError_mm[f] += childPad[f];
    plan.padCentroid_mm += childCentroid;
    plan.padShape_mm += childShape;

    pathDeviation(g, candidates, plan);
    return plan;
}

// What a span hands to the span above it, drawn: its rings' error against the full spline
// and its path's deviation, each with its children's.
struct SpanDrawn {
    double ringError_mm = 0.0;
    double pathDeviation_m = 0.0;
};

// The pads' error of `plan` at the drawn exaggeration.
double padError_mm(const SpanPlan& plan, const std::vector<double>& fs, double exaggeration) {
    for (std::size_t f = 0; f < fs.size(); ++f)
        if (fs[f] == exaggeration) return plan.padError_mm[f];
    return plan.padCentroid_mm + exaggeration * plan.padShape_mm;
}

// A span's mesh from `drawn` (buildCoarseMeshes), given what its children hand up.
SpanMesh finishSpan(const WellGeometry& drawn, const SpanPlan& plan, const std::vector<double>& fs,
                    const std::vector<std::size_t>* wholeRows,
                    const std::vector<SpanDrawn>& children, SpanDrawn& result) {
    const LodLevel level = spanLevel(drawn.options(), drawn.knotCount(), plan.depth);
    double childRingError_mm = 0.0, childDeviation_m = 0.0;
    if (plan.depth > 1) {
        const auto [from, to] = childSpans(plan.index, children.size());
        for (std::size_t c = from; c < to; ++c) {
            childRingError_mm = std::max(childRingError_mm, children[c].ringError_mm);
            childDeviation_m = std::max(childDeviation_m, children[c].pathDeviation_m);
        }
    }
    std::vector<std::size_t> rows;
    rows.reserve(plan.rows.size());
    for (const std::size_t row : plan.rows) rows.push_back(drawnRow(wholeRows, row));

    // The ring each kept row draws (the pads' polygon, or fewer spline points) against its
    // full spline, measured on the kept rows; between them the rings are close to the
    // straight line between theirs (the spline is linear in the pads).
    {
        std::optional<PeriodicSplineSampler> sampler;
        if (level.points > 0) sampler.emplace(drawn.knotCount(), level.points);
        for (std::size_t r : rows)
            result.ringError_mm = std::max(result.ringError_mm,
                                           ringError_mm(drawn, r, sampler ? &*sampler : nullptr));
        result.ringError_mm = std::max(result.ringError_mm, childRingError_mm);
    }
    // The tool turns between kept rows: a straight edge from a pad's point at one kept row to
    // the same pad's point at the next cuts inside the wall between them, by up to
    // r (1 - cos(turn / 2)) at the middle for a drawn radius r.
    const double exaggeration = drawn.options().radialExaggeration;
    const double drawnRadius_m =
        plan.maxRadius_mm * std::max(1.0, 2.0 * exaggeration - 1.0) / 1000.0;
    double deviation_m = plan.centreDeviation_m;
    for (std::size_t i = 0; i + 1 < rows.size(); ++i) {
        const std::size_t r0 = rows[i], r1 = rows[i + 1];
        if (!drawn.measured(r0) || !drawn.measured(r1)) continue;
        const double cosTurn =
            std::clamp(glm::dot(drawn.frame(r0).arm1, drawn.frame(r1).arm1), -1.0, 1.0);
        const double turn = std::acos(cosTurn);
        deviation_m = std::max(deviation_m, drawnRadius_m * (1.0 - std::cos(turn / 2.0)));
    }
    result.pathDeviation_m = deviation_m + childDeviation_m;

    SpanMesh mesh;
    mesh.depth = plan.depth;
    mesh.index = plan.index;
    mesh.firstSegment = plan.firstSegment;
    mesh.lastSegment = plan.lastSegment;
    mesh.firstRow = plan.firstRow;
    mesh.lastRow = plan.lastRow;
    // As for a segment (lod_levels.cpp): a drawn point lies within F r + (F - 1) r of the path.
    mesh.maxRadius_m = static_cast<float>(drawnRadius_m);
    // A full ring is the spline through its pads: pads within e of a line give a spline
    // within samplerNorm e of the line's spline, so the pads' error counts that much.
    mesh.error_mm =
        static_cast<float>(samplerNorm(drawn.sampler()) * padError_mm(plan, fs, exaggeration) +
                           result.ringError_mm + result.pathDeviation_m * 1000.0);
    mesh.mesh = buildRingMesh(drawn, rows, level.points);

    const glm::dvec3 a = toScene(drawn.centre(drawnRow(wholeRows, plan.firstRow)));
    const glm::dvec3 b = toScene(drawn.centre(drawnRow(wholeRows, plan.lastRow)));
    mesh.centre = glm::vec3((a + b) / 2.0);
    mesh.radius = static_cast<float>(plan.reach_m + childDeviation_m) + mesh.maxRadius_m;
    return mesh;
}

// Runs build(i) for i in [0, count) on `threads` threads (at most two: the machine's cores),
// stopping early once `cancel` is set.
template <class Build>
void eachOnThreads(std::size_t count, int threads, const std::atomic<bool>* cancel, Build build) {
    auto run = [&](std::size_t from, std::size_t step) {
        for (std::size_t i = from; i < count; i += step) {
            if (cancel && cancel->load()) return;
            build(i);
        }
    };
    if (threads > 1 && count > 1) {
        std::thread helper(run, 1, 2);
        run(0, 2);
        helper.join();
    } else {
        run(0, 1);
    }
}

// Every span's plan, depth 1 first, given those of depth 1 (`children`) or none; what it has
// planned when `cancel` is set.
std::vector<SpanPlan> planSpans(const WellGeometry& g, const std::vector<double>& fs, int threads,
                                const std::atomic<bool>* cancel,
                                std::vector<SpanPlan> children = {}) {
    std::vector<SpanPlan> out;
    const std::size_t segments = g.segmentCount();
    if (segments == 0) return out;
    const int depth = lodTreeDepth(segments);
    for (int d = children.empty() ? 1 : 2; d <= depth; ++d) {
        const std::size_t count = spanCount(d, segments);
        std::vector<SpanPlan> built(count);
        eachOnThreads(count, threads, cancel,
                      [&](std::size_t i) { built[i] = planSpan(g, d, i, children, fs); });
        if (cancel && cancel->load()) return out;
        for (SpanPlan& plan : children) out.push_back(std::move(plan));
        children = std::move(built);
    }
    for (SpanPlan& plan : children) out.push_back(std::move(plan));
    return out;
}

// The spans' meshes of `plans` (planSpans) drawn from `drawn`.
std::vector<SpanMesh> finishSpans(const WellGeometry& drawn, const std::vector<SpanPlan>& plans,
                                  const std::vector<double>& fs,
                                  const std::vector<std::size_t>* wholeRows, int threads,
                                  const std::atomic<bool>* cancel) {
    std::vector<SpanMesh> out(plans.size());
    std::vector<SpanDrawn> children, handed(plans.size());
    std::size_t begin = 0;
    while (begin < plans.size()) {
        std::size_t end = begin;
        while (end < plans.size() && plans[end].depth == plans[begin].depth) ++end;
        eachOnThreads(end - begin, threads, cancel, [&](std::size_t i) {
            out[begin + i] =
                finishSpan(drawn, plans[begin + i], fs, wholeRows, children, handed[begin + i]);
        });
        if (cancel && cancel->load()) {
            out.resize(begin);
            return out;
        }
        children.assign(handed.begin() + static_cast<std::ptrdiff_t>(begin),
                        handed.begin() + static_cast<std::ptrdiff_t>(end));
        begin = end;
    }
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
    const std::vector<double> fs{geometry.options().radialExaggeration};
    const std::vector<SpanPlan> plans = planSpans(geometry, fs, 2, cancel);
    if (cancel && cancel->load()) return {};
    return finishSpans(geometry, plans, fs, nullptr, 2, cancel);
}

std::vector<std::size_t> CoarsePlan::rows() const {
    std::vector<std::size_t> out;
    for (const SegmentPlan& segment : segments)
        for (const std::vector<std::size_t>& level : segment.levelRows)
            out.insert(out.end(), level.begin(), level.end());
    for (const SpanPlan& span : spans) out.insert(out.end(), span.rows.begin(), span.rows.end());
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

CoarsePlan planCoarseMeshes(const WellGeometry& whole, int firstLevel,
                            std::vector<double> exaggerations, int threads) {
    CoarsePlan plan;
    plan.firstLevel = std::max(firstLevel, 1);
    plan.exaggerations = std::move(exaggerations);
    const std::size_t count = whole.segmentCount();
    plan.segments.resize(count);
    if (count == 0) return plan;
    // Span by span of depth 1: its rows' knots once, for its segments' levels and itself (each
    // took them afresh).
    const auto knots = static_cast<std::size_t>(whole.knotCount());
    std::vector<SpanPlan> depth1(spanCount(1, count));
    eachOnThreads(depth1.size(), threads, nullptr, [&](std::size_t i) {
        const auto [s0, s1] = spanSegments(1, i, count);
        const std::size_t first = whole.segmentRows(s0).first;
        const std::size_t last = whole.segmentRows(s1).second;
        thread_local std::vector<double> values;
        if (values.size() < (last - first + 1) * knots) values.resize((last - first + 1) * knots);
        rowKnots(whole, first, last, values.data());
        for (std::size_t s = s0; s <= s1; ++s)
            plan.segments[s] =
                planSegmentLevels(whole, s, plan.firstLevel, std::numeric_limits<int>::max(),
                                  values.data() + (whole.segmentRows(s).first - first) * knots);
        depth1[i] = planSpan(whole, 1, i, {}, plan.exaggerations, values.data());
    });
    plan.spans = planSpans(whole, plan.exaggerations, threads, nullptr, std::move(depth1));
    return plan;
}

CoarseMeshes buildCoarseMeshes(const WellGeometry& drawn, const CoarsePlan& plan,
                               const std::vector<std::size_t>* wholeRows, int threads) {
    CoarseMeshes out;
    out.segments.resize(plan.segments.size());
    eachOnThreads(plan.segments.size(), threads, nullptr, [&](std::size_t s) {
        out.segments[s] = finishSegmentLevels(drawn, plan.segments[s], wholeRows);
    });
    out.spans = buildPlannedSpans(drawn, plan, wholeRows, threads);
    return out;
}

std::vector<SpanMesh> buildPlannedSpans(const WellGeometry& drawn, const CoarsePlan& plan,
                                        const std::vector<std::size_t>* wholeRows, int threads) {
    return finishSpans(drawn, plan.spans, plan.exaggerations, wholeRows, threads, nullptr);
}

CoarseMeshes buildCoarseMeshes(const WellGeometry& geometry, int firstLevel) {
    if (firstLevel < 1) {
        CoarseMeshes out;
        const std::size_t count = geometry.segmentCount();
        out.segments.resize(count);
        eachOnThreads(count, 2, nullptr, [&](std::size_t s) {
            out.segments[s] = buildCoarseSegment(geometry, s, firstLevel);
        });
        out.spans = buildSpanMeshes(geometry);
        return out;
    }
    return buildCoarseMeshes(
        geometry, planCoarseMeshes(geometry, firstLevel, {geometry.options().radialExaggeration}));
}

}  // namespace caliper3d::reconstruction

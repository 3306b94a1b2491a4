#include "reconstruction/mesh/lod_levels.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>

#include "reconstruction/mesh/swing_door.h"
#include "reconstruction/mesh/wall_colouring.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

namespace {

// Appends the ring of one row: `radii` at equal angles from arm 1, with outward normals and
// the colours of the geometry's WallColouring (departure from bit size without one). With a
// radial exaggeration F the ring is drawn F times larger about its own centre (the centroid
// of its area), so an off-centre tool does not push the drawn hole off the path and the
// shape stays the shape measured.
// A ring's point j in the scene frame: `plane` (drawnRing's, mm) placed in row's section.
glm::vec3 ringPoint(const SectionFrame& f, const Ned& c, const glm::dvec2& plane) {
    const glm::dvec2 drawn = plane / 1000.0;
    return toScene(c + drawn.x * f.arm1 + drawn.y * f.side);
}

void appendRing(const WellGeometry& g, Mesh& mesh, std::size_t row,
                const std::vector<double>& radii) {
    const int points = static_cast<int>(radii.size());
    const SectionFrame& f = g.frame(row);
    const Ned c = g.centre(row);
    const double bitRadius = g.bitRadius_mm(row);
    const WallColouring* colouring = g.options().colouring.get();
    const double exaggeration = g.options().radialExaggeration;
    const std::size_t base = mesh.positions.size();
    thread_local std::vector<glm::dvec2> plane;
    drawnRing(radii, exaggeration, plane);
    // A colouring per direction takes each point's angle from arm 1 about the ring's centre
    // (the mean of its points: near enough the centroid to choose a bin of 10 degrees).
    glm::dvec2 centre(0.0);
    const bool byDirection = colouring && colouring->byDirection();
    if (byDirection) {
        for (const glm::dvec2& q : plane) centre += q;
        centre /= static_cast<double>(std::max<std::size_t>(1, plane.size()));
    }
    for (int j = 0; j < points; ++j) {
        mesh.positions.emplace_back(ringPoint(f, c, plane[static_cast<std::size_t>(j)]));
        const double r = radii[static_cast<std::size_t>(j)];
        if (byDirection) {
            const glm::dvec2 d = plane[static_cast<std::size_t>(j)] - centre;
            mesh.colours.push_back(colouring->colour(row, r, glm::degrees(std::atan2(d.y, d.x))));
        } else {
            mesh.colours.push_back(colouring ? colouring->colour(row, r)
                                             : departureColour(r, bitRadius));
        }
    }
    // Outward normals: in-plane tangent (clockwise) crossed with the hole axis.
    for (int j = 0; j < points; ++j) {
        const glm::vec3& next =
            mesh.positions[base + static_cast<std::size_t>(j + 1 == points ? 0 : j + 1)];
        const glm::vec3& prev =
            mesh.positions[base + static_cast<std::size_t>(j == 0 ? points - 1 : j - 1)];
        const glm::dvec3 d = glm::dvec3(next - prev);
        glm::dvec3 normal = glm::cross(d, toScene(f.tangent));
        const double len = glm::length(normal);
        mesh.normals.emplace_back(
            len > 0 ? normal / len : toScene(f.direction(glm::two_pi<double>() * j / points)));
    }
}

bool measuredThrough(const WellGeometry& g, std::size_t first, std::size_t last) {
    for (std::size_t r = first; r <= last; ++r)
        if (!g.measured(r)) return false;
    return true;
}

// Rings of the measured rows among `rows`; a strip joins two consecutive ones only when every
// row between them is measured, so a no-data interval is a gap in the wall at every level
// (the path line still crosses it). The segment's first and last rows get the full spline at
// every level: neighbouring segments share those rings exactly, whatever level each shows,
// so no crack opens between them.
// ring(row, radii, joined) is called for each ring in order, `joined` when a strip joins it to
// the ring before.
template <class Ring>
void forEachLevelRing(const WellGeometry& g, const std::vector<std::size_t>& rows, int points,
                      Ring&& ring) {
    const int knots = g.knotCount();
    const int levelPoints = points > 0 ? points : knots;
    const int endPoints = g.sampler().samples();
    std::optional<PeriodicSplineSampler> sampler;
    if (points > 0 && points != endPoints) sampler.emplace(knots, points);
    std::vector<double> pads(static_cast<std::size_t>(knots));
    std::vector<double> radii;
    bool joinable = false;  // the last ring was rows[i - 1]'s
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (!g.measured(rows[i])) {
            joinable = false;
            continue;
        }
        g.sectionKnots(rows[i], pads.data());
        const bool end = i == 0 || i + 1 == rows.size();
        const int ringPoints = end ? endPoints : levelPoints;
        radii.resize(static_cast<std::size_t>(ringPoints));
        if (ringPoints == endPoints)
            g.sampler().sample(pads.data(), radii.data());
        else if (sampler)
            sampler->sample(pads.data(), radii.data());
        else
            radii = pads;
        ring(rows[i], radii, joinable && measuredThrough(g, rows[i - 1], rows[i]));
        joinable = true;
    }
}

// The rings of forEachLevelRing as a mesh, joined by closed strips.
// `strips`, when given, gets for each strip appended the row its first ring is of and where
// the strip starts in stripIndices.
Mesh buildLevel(const WellGeometry& g, const std::vector<std::size_t>& rows, int points,
                std::vector<std::pair<std::size_t, std::size_t>>* strips = nullptr) {
    Mesh mesh;
    mesh.positions.reserve(rows.size() *
                           static_cast<std::size_t>(points > 0 ? points : g.knotCount()));
    std::int32_t previousStart = 0;
    int previousPoints = 0;
    std::size_t previousRow = 0;
    forEachLevelRing(g, rows, points,
                     [&](std::size_t row, const std::vector<double>& radii, bool joined) {
                         const auto start = static_cast<std::int32_t>(mesh.positions.size());
                         const int ringPoints = static_cast<int>(radii.size());
                         appendRing(g, mesh, row, radii);
                         if (joined) {
                             if (strips)
                                 strips->emplace_back(previousRow, mesh.stripIndices.size());
                             appendClosedStrip(mesh.stripIndices, previousStart, previousPoints,
                                               start, ringPoints);
                         }
                         previousStart = start;
                         previousPoints = ringPoints;
                         previousRow = row;
                     });
    return mesh;
}

// The points of the rings of forEachLevelRing that a strip joins, into `box` (what
// buildLevel's strips draw), without building the mesh.
void extendByLevel(const WellGeometry& g, const std::vector<std::size_t>& rows, int points,
                   Box3& box) {
    const double exaggeration = g.options().radialExaggeration;
    std::vector<glm::dvec2> plane;
    std::vector<glm::dvec2> previous;  // the ring before, in its plane
    std::size_t previousRow = 0;
    bool previousIn = false;  // already in the box
    const auto extend = [&](std::size_t row, const std::vector<glm::dvec2>& ring) {
        const SectionFrame& f = g.frame(row);
        const Ned c = g.centre(row);
        for (const glm::dvec2& q : ring) box.extend(ringPoint(f, c, q));
    };
    forEachLevelRing(g, rows, points,
                     [&](std::size_t row, const std::vector<double>& radii, bool joined) {
                         drawnRing(radii, exaggeration, plane);
                         if (joined) {
                             if (!previousIn) extend(previousRow, previous);
                             extend(row, plane);
                         }
                         previousIn = joined;
                         std::swap(previous, plane);
                         previousRow = row;
                     });
}

}  // namespace

// The unit vectors at `points` equal angles from arm 1 (cos, sin), kept per thread for each
// count asked: a field's coarse meshes draw millions of rings of a few counts, and the sines
// and cosines took a fifth of their time.
const std::vector<glm::dvec2>& unitRing(std::size_t points) {
    thread_local std::map<std::size_t, std::vector<glm::dvec2>> rings;
    std::vector<glm::dvec2>& unit = rings[points];
    if (unit.size() != points) {
        unit.resize(points);
        for (std::size_t j = 0; j < points; ++j) {
            const double phi =
                glm::two_pi<double>() * static_cast<double>(j) / static_cast<double>(points);
            unit[j] = glm::dvec2(std::cos(phi), std::sin(phi));
        }
    }
    return unit;
}

void drawnRing(const std::vector<double>& radii_mm, double exaggeration,
               std::vector<glm::dvec2>& out) {
    const std::size_t points = radii_mm.size();
    const std::vector<glm::dvec2>& unit = unitRing(points);
    out.resize(points);
    for (std::size_t j = 0; j < points; ++j) out[j] = radii_mm[j] * unit[j];
    if (exaggeration == 1.0) return;
    const glm::dvec2 centroid = ringCentroid(out);
    for (glm::dvec2& p : out) p = centroid + (p - centroid) * exaggeration;
}

glm::dvec2 ringCentroid(const std::vector<glm::dvec2>& ring) {
    // Polygon centroid (shoelace); the tool axis when the ring has no area.
    const std::size_t points = ring.size();
    double area2 = 0.0;
    glm::dvec2 sum(0.0), centroid(0.0);
    for (std::size_t j = 0; j < points; ++j) {
        // (No modulo: an integer division at every point.)
        const glm::dvec2 &a = ring[j], &b = ring[j + 1 == points ? 0 : j + 1];
        const double cross = a.x * b.y - b.x * a.y;
        area2 += cross;
        sum += (a + b) * cross;
    }
    if (std::abs(area2) > 1e-6) centroid = sum / (3.0 * area2);
    return centroid;
}

double ringError_mm(const WellGeometry& g, std::size_t row, const PeriodicSplineSampler* level) {
    if (!g.measured(row)) return 0.0;
    const auto knots = static_cast<std::size_t>(g.knotCount());
    std::vector<double> pads(knots), full(static_cast<std::size_t>(g.sampler().samples()));
    g.sectionKnots(row, pads.data());
    g.sampler().sample(pads.data(), full.data());
    std::vector<double> coarse = pads;
    if (level) {
        coarse.resize(static_cast<std::size_t>(level->samples()));
        level->sample(pads.data(), coarse.data());
    }
    std::vector<glm::dvec2> fine, polygon;
    const double exaggeration = g.options().radialExaggeration;
    drawnRing(full, exaggeration, fine);
    drawnRing(coarse, exaggeration, polygon);
    // Each fine point's distance to the nearest edge of the coarse polygon.
    double worst = 0.0;
    for (const glm::dvec2& p : fine) {
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < polygon.size(); ++k) {
            const glm::dvec2 a = polygon[k], ab = polygon[(k + 1) % polygon.size()] - a;
            const double len2 = glm::dot(ab, ab);
            const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
            nearest = std::min(nearest, glm::length(p - (a + t * ab)));
        }
        worst = std::max(worst, nearest);
    }
    return worst;
}

double chordError(double radius, int points) {
    return radius * (1.0 - std::cos(glm::pi<double>() / std::max(points, 3)));
}

Mesh buildRingMesh(const WellGeometry& geometry, const std::vector<std::size_t>& rows, int points) {
    return buildLevel(geometry, rows, points);
}

std::vector<LodLevel> lodPyramid(const GeometryOptions& options) {
    const double t = options.shapeTolerance_mm;
    const int m = std::max(options.splinePoints, 6);
    return {
        {0.0, 0.0, m},
        {t, 0.05, std::max(m / 2, 6)},
        {4.0 * t, 0.25, std::max(m / 4, 6)},
        {16.0 * t, 1.0, 0},
    };
}

namespace {

// The spline knots of every measured row of [first, last], computed once for a segment (or
// for the span of depth 1 it is in: `shared`, row after row, lod_tree.cpp): its largest radius
// and every level's decimation read them.
struct SegmentKnots {
    SegmentKnots(const WellGeometry& g, std::size_t first_, std::size_t last_,
                 const double* shared = nullptr)
        : first(first_), last(last_), knots(static_cast<std::size_t>(g.knotCount())) {
        if (!shared) {
            owned.resize((last_ - first_ + 1) * knots);
            for (std::size_t r = first; r <= last; ++r)
                if (g.measured(r)) g.sectionKnots(r, owned.data() + (r - first) * knots);
            shared = owned.data();
        }
        values = shared;
    }
    SegmentKnots(const SegmentKnots&) = delete;
    SegmentKnots& operator=(const SegmentKnots&) = delete;
    double value(std::size_t row, std::size_t k) const { return values[(row - first) * knots + k]; }
    std::size_t first, last, knots;
    const double* values = nullptr;  // unmeasured rows: zeros, never read
    std::vector<double> owned;
};

// Rows `level` keeps among [first, last], a range within `segment`'s rows.
std::vector<std::size_t> keptRows(const WellGeometry& g, const SegmentKnots& segment,
                                  const LodLevel& level, std::size_t first, std::size_t last) {
    std::vector<std::size_t> rows;
    if (level.maxSpacing_m <= 0.0) {
        for (std::size_t r = first; r <= last; ++r) rows.push_back(r);
        return rows;
    }
    return swingDoor(
        g, last - first + 1, [first](std::size_t c) { return first + c; },
        [&segment, first](std::size_t c, std::size_t k) { return segment.value(first + c, k); },
        segment.knots, level);
}

glm::vec3 sceneCentre(const WellGeometry& g, std::size_t row) {
    return glm::vec3(toScene(g.centre(row)));
}

// Level 0 of a segment cut into parts about a quarter of its length (at least
// kMinPartRows rows each), each with a reduced copy: every spline point, the rows level 1's
// shape tolerance keeps. Both copies end on the same full rings, so neighbouring parts and
// segments meet without a crack whichever copy each shows.
// `maxRadius_m`: the segment's largest drawn radius (SegmentMesh::maxRadius_m).
std::vector<DetailPart> detailParts(
    const WellGeometry& g, const SegmentKnots& knots, const std::vector<LodLevel>& pyramid,
    float maxRadius_m, const Mesh& full,
    const std::vector<std::pair<std::size_t, std::size_t>>& strips) {
    constexpr std::size_t kParts = 4, kMinPartRows = 16;
    const std::size_t first = knots.first, last = knots.last;
    const std::size_t parts = std::min(kParts, (last - first) / kMinPartRows);
    std::vector<DetailPart> out;
    if (parts < 2) return out;
    const std::vector<double>& depth = g.table().depth_m;
    LodLevel reducedLevel = pyramid[1];
    reducedLevel.points = pyramid[0].points;
    std::size_t from = first;
    for (std::size_t p = 1; p <= parts; ++p) {
        std::size_t to = last;
        if (p < parts) {
            const double target =
                depth[first] + (depth[last] - depth[first]) * static_cast<double>(p) / parts;
            const auto it =
                std::lower_bound(depth.begin() + static_cast<std::ptrdiff_t>(from),
                                 depth.begin() + static_cast<std::ptrdiff_t>(last), target);
            to = std::clamp(static_cast<std::size_t>(it - depth.begin()), from + 1, last - 1);
        }
        DetailPart part;
        part.firstRow = from;
        part.lastRow = to;
        // Strips are in row order: those whose first ring is a row of [from, to).
        auto rowBelow = [](const std::pair<std::size_t, std::size_t>& s, std::size_t row) {
            return s.first < row;
        };
        const auto begin = std::lower_bound(strips.begin(), strips.end(), from, rowBelow);
        const auto end = std::lower_bound(begin, strips.end(), to, rowBelow);
        part.stripBegin = begin == strips.end() ? full.stripIndices.size() : begin->second;
        part.stripEnd = end == strips.end() ? full.stripIndices.size() : end->second;
        const glm::vec3 a = sceneCentre(g, from), b = sceneCentre(g, to);
        part.centre = (a + b) / 2.0f;
        part.radius = glm::length(b - a) / 2.0f + maxRadius_m;
        part.reduced =
            buildLevel(g, keptRows(g, knots, reducedLevel, from, to), reducedLevel.points);
        out.push_back(std::move(part));
        from = to;
    }
    return out;
}

}  // namespace

std::vector<std::size_t> decimatedRows(const WellGeometry& g, std::size_t first, std::size_t last,
                                       const LodLevel& level) {
    return keptRows(g, SegmentKnots(g, first, last), level, first, last);
}

namespace {

// What every level's switch needs of a segment: its largest drawn radius, each level's drawn
// shape error, its depths and its bounding sphere about the centres of `first` and `last`
// (its end rows in `g`).
void segmentBounds(SegmentMesh& out, const WellGeometry& g, const std::vector<LodLevel>& pyramid,
                   double maxRadius_mm, std::size_t first, std::size_t last) {
    out.top_m = g.table().depth_m[first];
    out.bottom_m = g.table().depth_m[last];
    const double exaggeration = g.options().radialExaggeration;
    const double drawn_mm = maxRadius_mm * exaggeration;
    // Sections are drawn about their centroids, within maxRadius of the path: a drawn point
    // is within F maxRadius + (F - 1) maxRadius of it.
    out.maxRadius_m =
        static_cast<float>(maxRadius_mm * std::max(1.0, 2.0 * exaggeration - 1.0) / 1000.0);
    for (std::size_t i = 0; i < pyramid.size(); ++i) {
        const LodLevel& l = pyramid[i];
        const double error =
            i == 0 ? 0.0
                   : l.tolerance_mm * exaggeration +
                         chordError(drawn_mm, l.points > 0 ? l.points : g.knotCount());
        out.levelError_mm.push_back(static_cast<float>(error));
    }
    const glm::dvec3 a = toScene(g.centre(first)), b = toScene(g.centre(last));
    out.centre = glm::vec3((a + b) / 2.0);
    out.radius = static_cast<float>(glm::length(b - a) / 2.0) + out.maxRadius_m;
}

// The largest knot value of a segment (rows without data hold zeros) and the triangles its
// level 0 draws.
std::pair<double, std::size_t> segmentSize(const WellGeometry& g, const SegmentKnots& knots,
                                           const LodLevel& finest) {
    double maxRadius_mm = 0.0;
    const std::size_t count = (knots.last - knots.first + 1) * knots.knots;
    for (std::size_t i = 0; i < count; ++i) maxRadius_mm = std::max(maxRadius_mm, knots.values[i]);
    std::size_t triangles = 0;
    for (std::size_t r = knots.first; r < knots.last; ++r)
        if (g.measured(r) && g.measured(r + 1))
            triangles += 2 * static_cast<std::size_t>(finest.points);
    return {maxRadius_mm, triangles};
}

}  // namespace

std::size_t drawnRow(const std::vector<std::size_t>* wholeRows, std::size_t row) {
    if (!wholeRows) return row;
    const auto it = std::lower_bound(wholeRows->begin(), wholeRows->end(), row);
    if (it == wholeRows->end() || *it != row)
        throw std::logic_error("drawnRow: row " + std::to_string(row) + " is not held");
    return static_cast<std::size_t>(it - wholeRows->begin());
}

SegmentPlan planSegmentLevels(const WellGeometry& whole, std::size_t segment, int from, int to,
                              const double* knotValues) {
    if (segment >= whole.segmentCount())
        throw std::out_of_range("planSegmentLevels: no segment " + std::to_string(segment));
    const std::vector<LodLevel> pyramid = lodPyramid(whole.options());
    to = std::min(to, static_cast<int>(pyramid.size()));
    from = std::clamp(from, 1, to);
    SegmentPlan plan;
    plan.index = segment;
    std::tie(plan.firstRow, plan.lastRow) = whole.segmentRows(segment);
    plan.firstLevel = from;
    const SegmentKnots knots(whole, plan.firstRow, plan.lastRow, knotValues);
    std::tie(plan.maxRadius_mm, plan.fullDetailTriangles) =
        segmentSize(whole, knots, pyramid.front());
    for (int i = from; i < to; ++i)
        plan.levelRows.push_back(keptRows(whole, knots, pyramid[static_cast<std::size_t>(i)],
                                          plan.firstRow, plan.lastRow));
    return plan;
}

SegmentMesh finishSegmentLevels(const WellGeometry& drawn, const SegmentPlan& plan,
                                const std::vector<std::size_t>* wholeRows) {
    const std::vector<LodLevel> pyramid = lodPyramid(drawn.options());
    SegmentMesh out;
    out.index = plan.index;
    out.firstRow = plan.firstRow;
    out.lastRow = plan.lastRow;
    const std::size_t first = drawnRow(wholeRows, plan.firstRow);
    const std::size_t last = drawnRow(wholeRows, plan.lastRow);
    out.firstLevel = plan.firstLevel;
    out.fullDetailTriangles = plan.fullDetailTriangles;
    std::vector<std::size_t> rows;
    for (std::size_t i = 0; i < plan.levelRows.size(); ++i) {
        rows.clear();
        for (const std::size_t row : plan.levelRows[i]) rows.push_back(drawnRow(wholeRows, row));
        const int level = plan.firstLevel + static_cast<int>(i);
        out.levels.push_back(
            buildLevel(drawn, rows, pyramid[static_cast<std::size_t>(level)].points));
    }
    segmentBounds(out, drawn, pyramid, plan.maxRadius_mm, first, last);
    return out;
}

Box3 plannedSegmentBox(const WellGeometry& drawn, const SegmentPlan& plan,
                       const std::vector<std::size_t>* wholeRows) {
    const std::vector<LodLevel> pyramid = lodPyramid(drawn.options());
    Box3 box;
    std::vector<std::size_t> rows;
    for (std::size_t i = 0; i < plan.levelRows.size(); ++i) {
        rows.clear();
        for (const std::size_t row : plan.levelRows[i]) rows.push_back(drawnRow(wholeRows, row));
        const int level = plan.firstLevel + static_cast<int>(i);
        extendByLevel(drawn, rows, pyramid[static_cast<std::size_t>(level)].points, box);
    }
    return box;
}

SegmentMesh buildSegmentLevels(const WellGeometry& geometry, std::size_t segment, int from,
                               int to) {
    if (segment >= geometry.segmentCount())
        throw std::out_of_range("buildSegmentLevels: no segment " + std::to_string(segment));
    if (from >= 1)
        return finishSegmentLevels(geometry, planSegmentLevels(geometry, segment, from, to),
                                   nullptr);
    const std::vector<LodLevel> pyramid = lodPyramid(geometry.options());
    to = std::min(to, static_cast<int>(pyramid.size()));
    const auto [first, last] = geometry.segmentRows(segment);
    SegmentMesh out;
    out.index = segment;
    out.firstRow = first;
    out.lastRow = last;
    out.firstLevel = 0;

    const SegmentKnots knots(geometry, first, last);
    double maxRadius_mm = 0.0;
    std::tie(maxRadius_mm, out.fullDetailTriangles) = segmentSize(geometry, knots, pyramid.front());
    segmentBounds(out, geometry, pyramid, maxRadius_mm, first, last);
    for (int i = 0; i < to; ++i) {
        const LodLevel& l = pyramid[static_cast<std::size_t>(i)];
        const std::vector<std::size_t> rows = keptRows(geometry, knots, l, first, last);
        if (i == 0) {
            std::vector<std::pair<std::size_t, std::size_t>> strips;
            out.levels.push_back(buildLevel(geometry, rows, l.points, &strips));
            out.parts =
                detailParts(geometry, knots, pyramid, out.maxRadius_m, out.levels.back(), strips);
            out.partError_mm =
                static_cast<float>(pyramid[1].tolerance_mm * geometry.options().radialExaggeration);
        } else {
            out.levels.push_back(buildLevel(geometry, rows, l.points));
        }
    }
    return out;
}

SegmentMesh buildSegmentMesh(const WellGeometry& geometry, std::size_t segment) {
    return buildSegmentLevels(geometry, segment, 0, std::numeric_limits<int>::max());
}

SegmentMesh buildCoarseSegment(const WellGeometry& geometry, std::size_t segment, int firstLevel) {
    return buildSegmentLevels(geometry, segment, firstLevel, std::numeric_limits<int>::max());
}

std::vector<glm::vec3> sectionRing(const WellGeometry& geometry, std::size_t row) {
    if (row >= geometry.table().rowCount() || !geometry.measured(row)) return {};
    return buildLevel(geometry, {row}, geometry.sampler().samples()).positions;
}

}  // namespace caliper3d::reconstruction

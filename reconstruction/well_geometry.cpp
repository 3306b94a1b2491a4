#include "reconstruction/well_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include "io/casing_program.h"
#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/mesh/wall_colouring.h"
#include "reconstruction/parallel/ordered_blocks.h"
#include "reconstruction/parallel/prefault.h"
#include "reconstruction/path/course_dogleg.h"
#include "reconstruction/path/survey_interpolation.h"
#include "reconstruction/section/arm_geometry.h"
#include "reconstruction/section/invalid_arm_readings.h"
#include "reconstruction/section/section_coverage.h"
#include "reconstruction/segment_length.h"

namespace caliper3d::reconstruction {

namespace {

double valueAt(const std::vector<double>& curve, std::size_t row) {
    return row < curve.size() ? curve[row] : io::kNaN;
}

// The value each block of `blockRows` rows starts from when nulls carry the
// last finite reading forward (0 before the first), so that a null
// orientation reading never produces a NaN position: one backward search per
// block, usually of one row.
std::vector<double> carriedIntoBlocks(const std::vector<double>& curve, std::size_t rows,
                                      std::size_t blockRows, double carried) {
    std::vector<double> out;
    for (std::size_t first = 0; first < rows; first += blockRows) {
        out.push_back(carried);
        const std::size_t last = std::min({rows, first + blockRows, curve.size()});
        for (std::size_t i = last; i-- > first;) {
            if (std::isfinite(curve[i])) {
                carried = curve[i];
                break;
            }
        }
    }
    return out;
}

// Rows per block of the parallel construction: large enough that a block's
// start-up (a backward search, one extra direction) is negligible, small
// enough that two workers share a well evenly.
constexpr std::size_t kBlockRows = 4096;

// A table the geometry can be built from: two arms, two sections, depths increasing.
void checkDrawable(const io::SectionTable& t) {
    const std::size_t rows = t.rowCount();
    if (t.armCount < 2)
        throw std::invalid_argument(t.source + ": need at least 2 arms to draw a section");
    if (rows < 2)
        throw std::invalid_argument(t.source + ": need at least 2 sections to draw a hole");
    for (std::size_t i = 1; i < rows; ++i) {
        if (!(t.depth_m[i] > t.depth_m[i - 1]))
            throw std::invalid_argument(t.source + ": depths must increase (row " +
                                        std::to_string(i + 1) + ")");
    }
}

}  // namespace

WellGeometry::WellGeometry(std::shared_ptr<const io::SectionTable> table,
                           const GeometryOptions& options)
    : m_table(std::move(table)),
      m_options(options),
      m_placed(std::make_shared<Placement>()),
      m_sampler(sectionKnotCount(m_table ? m_table->armCount : 3), options.splinePoints) {
    checkDrawable(*m_table);
    markMeasuredRows();
    if (cancelled()) throw GeometryCancelled();
    computePathAndOrientation();
    cutSegments();
}

void WellGeometry::markMeasuredRows() {
    const io::SectionTable& t = *m_table;
    const std::size_t rows = t.rowCount();
    // Sections with too few valid arms have no shape: a log without any
    // section that has one is bad input, not a hole of invented gauge.
    const int needed = minValidArms(t.armCount, m_options.minValidArmFraction);
    m_placed->measured.resize(rows);
    for (std::size_t i = 0; i < rows; ++i) {
        if (i % 65536 == 0 && cancelled()) throw GeometryCancelled();
        m_placed->measured[i] = countValidArms(t.radii(i), t.armCount, m_options.minArmRadius_mm,
                                               m_options.maxArmRadius_mm) >= needed;
        m_placed->measuredRows += m_placed->measured[i];
    }
    if (m_placed->measuredRows == 0) {
        // Why and where: the kinds of invalid reading, and the first section.
        InvalidArmReadings invalid;
        invalid.add(t, m_options.minValidArmFraction, m_options.minArmRadius_mm,
                    m_options.maxArmRadius_mm);
        char where[64] = "";
        if (rows > 0) std::snprintf(where, sizeof where, "; the first at %.2f m", t.depth_m[0]);
        throw std::invalid_argument(t.source + ": no usable caliper data: none of its " +
                                    std::to_string(rows) + " sections has at least " +
                                    std::to_string(needed) + " of its " +
                                    std::to_string(t.armCount) + " arms with a valid reading: " +
                                    describeInvalidArmReadings(invalid, m_options.minArmRadius_mm,
                                                               m_options.maxArmRadius_mm) +
                                    where);
    }
}

bool WellGeometry::cancelled() const {
    return m_options.cancel && m_options.cancel->load(std::memory_order_relaxed);
}

void WellGeometry::computePathAndOrientation() {
    const io::SectionTable& t = *m_table;
    const std::size_t rows = t.rowCount();
    const bool fromSurvey = !m_options.survey.empty();
    // The workers write 64 bytes per row into fresh memory: its pages are
    // faulted in on every worker at once first, not by the first writer.
    const int threads = std::max(1, m_options.threads);
    if (fromSurvey) {
        m_placed->path = interpolateSurveyPath(tiedToSurface(m_options.survey), t.depth_m);
    } else {
        m_placed->path.reserve(rows);
        prefaultPages(m_placed->path.data(), rows * sizeof(PathPoint), threads, m_options.cancel);
        if (cancelled()) throw GeometryCancelled();  // before the rest is faulted in by one thread
        m_placed->path.resize(rows);
    }
    m_placed->orientation.resize(rows);
    // Each row's unit tangent, from the sines and cosines its step took, for the dogleg severity.
    std::vector<glm::dvec3> tangents(fromSurvey ? 0 : rows);

    // Each block computes its rows' minimum-curvature steps from one set of
    // sines and cosines per row, and which reading orients each row; the positions are then the
    // running sum of the steps, added block after block in row order exactly as a single loop adds
    // them.
    const std::size_t blocks = (rows + kBlockRows - 1) / kBlockRows;
    std::vector<double> startInc, startAzi;
    if (!fromSurvey) {
        const std::optional<PathPoint>& from = m_options.continueFrom;
        startInc = carriedIntoBlocks(t.devi_deg, rows, kBlockRows, from ? from->inc_deg : 0.0);
        startAzi = carriedIntoBlocks(t.hazi_deg, rows, kBlockRows, from ? from->azi_deg : 0.0);
    }
    forEachBlockInOrder(
        blocks, threads,
        [&](std::size_t block, std::size_t) {
            if (cancelled()) return;
            const std::size_t first = block * kBlockRows, last = std::min(rows, first + kBlockRows);
            if (!fromSurvey)
                computeSteps(first, last, startInc[block], startAzi[block], tangents.data());
            computeOrientation(first, last);
        },
        [&](std::size_t block) {
            if (fromSurvey || cancelled()) return;
            const std::size_t first = block * kBlockRows, last = std::min(rows, first + kBlockRows);
            for (std::size_t i = std::max<std::size_t>(first, 1); i < last; ++i) {
                PathPoint& p = m_placed->path[i];
                const PathPoint& prev = m_placed->path[i - 1];
                p.north = prev.north + p.north;
                p.east = prev.east + p.east;
                p.tvd = prev.tvd + p.tvd;
            }
        });
    if (cancelled()) throw GeometryCancelled();
    // From the log's own DEVI and HAZI, dogleg severity over a course length, not between
    // samples (a survey's is between its stations already).
    if (!fromSurvey) setCourseLengthDls(m_placed->path, tangents);
}

// Segments of equal length; consecutive segments share their boundary row.
void WellGeometry::cutSegments() {
    const io::SectionTable& t = *m_table;
    const std::size_t rows = t.rowCount();
    if (!(m_options.segmentLength_m > 0.0))
        m_options.segmentLength_m = autoSegmentLength(t.depth_m);
    const double segment = std::max(m_options.segmentLength_m, 1e-3);
    std::size_t first = 0;
    while (first + 1 < rows) {
        const double limit = t.depth_m[first] + segment;
        std::size_t last = first + 1;
        while (last + 1 < rows && t.depth_m[last + 1] <= limit) ++last;
        m_placed->segments.emplace_back(first, last);
        first = last;
    }
}

// Path points of rows [first, last) from the log's DEVI and HAZI (nulls carry
// the last reading forward, starting from `inc` and `azi`), each holding its minimum-curvature step
// from the row before in north/east/tvd until the constructor sums them.
void WellGeometry::computeSteps(std::size_t first, std::size_t last, double inc, double azi,
                                glm::dvec3* tangents) {
    const io::SectionTable& t = *m_table;
    const bool departureKnown = holeAzimuthKnown();
    HoleDirection previous(inc, azi), current = previous;
    for (std::size_t i = first; i < last; ++i) {
        const double devi = valueAt(t.devi_deg, i), hazi = valueAt(t.hazi_deg, i);
        if (std::isfinite(devi)) inc = devi;
        if (std::isfinite(hazi)) azi = hazi;
        current.update(inc, azi);
        PathPoint& p = m_placed->path[i];
        p = PathPoint{};
        p.md = t.depth_m[i];
        p.inc_deg = inc;
        p.azi_deg = azi;
        if (i > 0) {
            const double mdBefore = t.depth_m[i - 1];
            const MinimumCurvatureStep s = minimumCurvatureStep(mdBefore, previous, p.md, current);
            p.north = s.dNorth;
            p.east = s.dEast;
            p.tvd = s.dTvd;
            p.dogleg_deg = glm::degrees(s.dogleg_rad);
            p.dls_degPer30m = doglegSeverity_degPer30m(p.dogleg_deg, p.md - mdBefore);
        } else if (m_options.continueFrom) {
            p = *m_options.continueFrom;  // placed by the stretch before, in absolute terms
            current.set(p.inc_deg, p.azi_deg);
            inc = p.inc_deg;
            azi = p.azi_deg;
        } else {
            // Measured depth counts from the depth reference at the wellhead: the
            // first section is tied to a vertical station there (docs/conventions.md,
            // "Tie-in"), so a log starting at 27 m starts 27 m down, not at the origin.
            const SurveyStation top = surfaceTieIn({p.md, inc, azi});
            const MinimumCurvatureStep s = minimumCurvatureStep(
                top.md, HoleDirection(top.inc_deg, top.azi_deg), p.md, current);
            p.north = s.dNorth;
            p.east = s.dEast;
            p.tvd = s.dTvd;
        }
        if (!departureKnown && !(i == 0 && m_options.continueFrom)) {
            // An inclined hole of unknown azimuth: its TVD is known, the direction of its
            // departure is not, so it is drawn without one (docs/conventions.md, "Hole azimuth").
            p.north = 0.0;
            p.east = 0.0;
        }
        tangents[i] = {current.sinInc * current.cosAzi, current.sinInc * current.sinAzi,
                       current.cosInc};
        previous = current;
    }
}

// Arm 1 (docs/conventions.md, "Section plane and arm 1 in a deviated hole"): P1AZ in
// near-vertical holes, RB from the high side in steep ones (where P1AZ, a horizontal
// projection, loses precision) or when P1AZ is missing; P1AZ when RB is missing. A row with neither
// keeps arm 1 north and is counted as unoriented.
// Which reading places arm 1 on each of rows [first, last): RB in a steep hole or where P1AZ is
// missing, else P1AZ; neither, unoriented.
void WellGeometry::computeOrientation(std::size_t first, std::size_t last) {
    const io::SectionTable& t = *m_table;
    for (std::size_t i = first; i < last; ++i) {
        const double inc = m_placed->path[i].inc_deg;
        const double p1az = valueAt(t.p1az_deg, i);
        const double rb = valueAt(t.rb_deg, i);
        const bool steep = inc > m_options.steepInclination_deg;
        if (std::isfinite(rb) && (steep || !std::isfinite(p1az)))
            m_placed->orientation[i] = Orientation::RelativeBearing;
        else
            m_placed->orientation[i] =
                std::isfinite(p1az) ? Orientation::PadAzimuth : Orientation::Unoriented;
    }
}

// HoleDirection's sines and cosines are std::sin's and std::cos's of the angles, so the frame
// is the one a running HoleDirection along the rows gives, bit for bit.
SectionFrame WellGeometry::frame(std::size_t row) const {
    const PathPoint& p = m_placed->path[row];
    const HoleDirection direction(p.inc_deg, p.azi_deg);
    if (m_placed->orientation[row] == Orientation::RelativeBearing)
        return frameFromRelativeBearing(direction, valueAt(m_table->rb_deg, row));
    const double p1az = valueAt(m_table->p1az_deg, row);
    return frameFromPadAzimuth(direction, std::isfinite(p1az) ? p1az : 0.0);
}

Ned WellGeometry::centre(std::size_t row) const {
    const PathPoint& p = m_placed->path[row];
    return Ned(p.north, p.east, p.tvd) + m_options.wellheadOffset;
}

double WellGeometry::bitRadius_mm(std::size_t row) const {
    if (!m_table->casing.empty() && row < m_table->rowCount())
        if (const io::CasingString* c = io::casingAt(m_table->casing, m_table->depth_m[row]))
            return c->innerDiameter_mm / 2.0;
    return valueAt(m_table->bitSize_mm, row) / 2.0;
}

int WellGeometry::repairRadii(std::size_t row, double* out) const {
    const int n = m_table->armCount;
    const double* r = m_table->radii(row);
    const double lo = m_options.minArmRadius_mm, hi = m_options.maxArmRadius_mm;
    auto valid = [lo, hi](double v) { return std::isfinite(v) && v > lo && v <= hi; };
    int good = 0;
    for (int k = 0; k < n; ++k) {
        out[k] = r[k];
        good += valid(r[k]) ? 1 : 0;
    }
    if (good == n) return 0;
    if (good == 0) {
        const double fallback = std::isfinite(bitRadius_mm(row)) ? bitRadius_mm(row) : 100.0;
        std::fill(out, out + n, fallback);
        return n;
    }
    // Linear interpolation around the section between the nearest valid arms:
    // a missing arm never becomes a spike or a notch in the mesh.
    for (int k = 0; k < n; ++k) {
        if (valid(r[k])) continue;
        int before = 1, after = 1;
        while (!valid(r[(k - before + n) % n])) ++before;
        while (!valid(r[(k + after) % n])) ++after;
        const double a = r[(k - before + n) % n], b = r[(k + after) % n];
        out[k] = a + (b - a) * before / static_cast<double>(before + after);
    }
    return n - good;
}

int sectionKnotCount(int armCount) {
    return armCount == 2 ? kTwoPadKnots : armCount;
}

void twoPadCircle(double r1_mm, double r2_mm, double* knots) {
    // The circle through both pads, centred half-way between them: centre c
    // along arm 1, radius R; seen from the tool axis at angle phi from arm 1
    // its radius is c cos phi + sqrt(R^2 - c^2 sin^2 phi) (phi = 0 gives r1,
    // 180 deg gives r2). Symmetric about the arm line, so either sense of phi.
    const double c = (r1_mm - r2_mm) / 2.0, R = (r1_mm + r2_mm) / 2.0;
    for (int j = 0; j < kTwoPadKnots; ++j) {
        const double phi = glm::two_pi<double>() * j / kTwoPadKnots;
        const double s = c * std::sin(phi);
        knots[j] = c * std::cos(phi) + std::sqrt(std::max(0.0, R * R - s * s));
    }
}

int WellGeometry::sectionKnots(std::size_t row, double* out) const {
    if (m_table->armCount != 2) return repairRadii(row, out);
    double pads[2];
    const int repaired = repairRadii(row, pads);
    twoPadCircle(pads[0], pads[1], out);
    return repaired;
}

std::vector<NoDataInterval> WellGeometry::noDataIntervals() const {
    return reconstruction::noDataIntervals(m_placed->measured, m_table->depth_m);
}

WellGeometry WellGeometry::restyled(double radialExaggeration,
                                    std::shared_ptr<const WallColouring> colouring) const {
    if (colouring && colouring->rowCount() != m_table->rowCount())
        throw std::invalid_argument(m_table->source + ": a wall colouring of " +
                                    std::to_string(colouring->rowCount()) + " rows for a well of " +
                                    std::to_string(m_table->rowCount()));
    WellGeometry out(*this);
    out.m_options.radialExaggeration = radialExaggeration;
    out.m_options.colouring = std::move(colouring);
    out.m_options.cancel = nullptr;  // built already; the token may be gone
    return out;
}

WellGeometry WellGeometry::sampled(std::size_t maxRows) const {
    const std::size_t rows = m_table->rowCount();
    if (rows <= std::max<std::size_t>(maxRows, 2)) {
        WellGeometry out(*this);
        out.m_options.colouring.reset();
        out.m_options.cancel = nullptr;
        return out;
    }
    return sampled(everyKthRow(rows, maxRows));
}

std::vector<std::size_t> everyKthRow(std::size_t rows, std::size_t maxRows) {
    std::vector<std::size_t> keep;
    if (rows == 0) return keep;
    const std::size_t stride = std::max<std::size_t>(1, rows / std::max<std::size_t>(maxRows, 1));
    keep.reserve(rows / stride + 2);
    for (std::size_t row = 0; row < rows; row += stride) keep.push_back(row);
    if (keep.back() != rows - 1) keep.push_back(rows - 1);
    return keep;
}

WellGeometry WellGeometry::sampled(const std::vector<std::size_t>& keep) const {
    WellGeometry out(*this);
    out.m_options.colouring.reset();
    out.m_options.cancel = nullptr;
    auto table = std::make_shared<io::SectionTable>(m_table->rows(0, 0));
    table->reserve(keep.size());
    auto placed = std::make_shared<Placement>();
    placed->path.reserve(keep.size());
    placed->orientation.reserve(keep.size());
    placed->measured.reserve(keep.size());
    for (const std::size_t row : keep) {
        table->appendRows(*m_table, row, row + 1);
        placed->path.push_back(m_placed->path[row]);
        placed->orientation.push_back(m_placed->orientation[row]);
        placed->measured.push_back(m_placed->measured[row]);
        placed->measuredRows += m_placed->measured[row];
    }
    out.m_table = std::move(table);
    out.m_placed = std::move(placed);
    out.cutSegments();
    return out;
}

SegmentMesh WellGeometry::buildSegment(std::size_t segment) const {
    return buildSegmentMesh(*this, segment);
}

std::vector<std::size_t> pathLineRows(const WellGeometry& geometry, double spacing_m,
                                      double after_m) {
    const auto& depth = geometry.table().depth_m;
    std::vector<std::size_t> rows;
    double next = -1.0e300;
    for (std::size_t row = 0; row < depth.size(); ++row) {
        if (depth[row] <= after_m) continue;
        if (depth[row] < next && row + 1 != depth.size()) continue;
        rows.push_back(row);
        next = depth[row] + spacing_m;
    }
    return rows;
}

std::vector<std::size_t> simplifiedLine(const std::vector<glm::vec3>& line, float tolerance,
                                        float* error) {
    // Written here: boost::geometry::simplify gives the points kept, not which they are nor
    // how far the line kept strays, which the path's level of detail switches by.
    const std::size_t n = line.size();
    if (error) *error = 0.0f;
    if (n <= 2) {
        std::vector<std::size_t> all(n);
        for (std::size_t i = 0; i < n; ++i) all[i] = i;
        return all;
    }
    const auto distance = [&line](std::size_t p, std::size_t a, std::size_t b) {
        const glm::vec3 ab = line[b] - line[a];
        const float length2 = glm::dot(ab, ab);
        const float t = length2 > 0.0f
                            ? std::clamp(glm::dot(line[p] - line[a], ab) / length2, 0.0f, 1.0f)
                            : 0.0f;
        return glm::length(line[p] - (line[a] + t * ab));
    };
    std::vector<char> keep(n, 0);
    keep.front() = keep.back() = 1;
    std::vector<std::pair<std::size_t, std::size_t>> stretches{{0, n - 1}};
    while (!stretches.empty()) {
        const auto [a, b] = stretches.back();
        stretches.pop_back();
        float worst = 0.0f;
        std::size_t at = a;
        for (std::size_t p = a + 1; p < b; ++p)
            if (const float d = distance(p, a, b); d > worst) {
                worst = d;
                at = p;
            }
        if (worst > tolerance) {
            keep[at] = 1;
            stretches.emplace_back(a, at);
            stretches.emplace_back(at, b);
        } else if (error) {
            *error = std::max(*error, worst);
        }
    }
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < n; ++i)
        if (keep[i]) kept.push_back(i);
    return kept;
}

std::vector<glm::vec3> pathLine(const WellGeometry& geometry, double spacing_m, double after_m) {
    std::vector<glm::vec3> points;
    for (const std::size_t row : pathLineRows(geometry, spacing_m, after_m))
        points.emplace_back(toScene(geometry.centre(row)));
    return points;
}

}  // namespace caliper3d::reconstruction

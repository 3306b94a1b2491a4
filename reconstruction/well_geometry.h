#pragma once

#include <atomic>
#include <cstddef>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "io/section_table.h"
#include "reconstruction/mesh/mesh.h"
#include "reconstruction/parallel/fill_array.h"
#include "reconstruction/path/minimum_curvature.h"
#include "reconstruction/section/periodic_spline.h"
#include "reconstruction/section/section_coverage.h"
#include "reconstruction/section/section_frame.h"

namespace caliper3d::reconstruction {

class WallColouring;

struct GeometryOptions {
    int splinePoints = 48;               // M: samples of the closed spline per section
    double segmentLength_m = 1.0;        // the well is cut into segments of this length
    double shapeTolerance_mm = 0.5;      // level 1's shape error; coarser levels x4, x16
                                         //   (reconstruction/mesh/lod_levels.h)
    double steepInclination_deg = 15.0;  // above this, arm 1 comes from RB when present
    // Display only: each section drawn this many times larger about its own centre (the
    // centroid of its area), so that a long well seen whole is more than a line. The path
    // and the analysis never use it.
    double radialExaggeration = 1.0;
    // Display only: the wall's colours; null: departure from bit size
    // (reconstruction/mesh/wall_colouring.h). One value per row of this well's table.
    std::shared_ptr<const WallColouring> colouring;
    glm::dvec3 wellheadOffset{0.0, 0.0, 0.0};  // NED offset of this wellhead from the scene origin
    // A deviation survey (--survey) replaces the log's DEVI/HAZI for the path
    // when not empty: the path is interpolated along its minimum-curvature arcs.
    std::vector<SurveyStation> survey;
    // Arm readings outside [minArmRadius_mm, maxArmRadius_mm] (a closed,
    // stuck or over-reaching arm) are treated as missing and interpolated.
    double minArmRadius_mm = 0.0;    // readings <= this are missing
    double maxArmRadius_mm = 1.0e9;  // the tool's reach; no limit by default
    // A section with fewer valid arms than minValidArms(armCount, this) has no
    // data: it is neither drawn nor analysed (docs/analysis.md, "No data").
    double minValidArmFraction = kDefaultMinValidArmFraction;
    // A stretch of a longer log read in chunks (reconstruction/load/well_load_pipeline.h): its
    // first row is a row the stretch before already placed, at this path point (position,
    // carried inclination and azimuth). The rows after it are then placed exactly as in the
    // whole log's geometry, bit for bit. Unused with a survey (its path is per row already).
    std::optional<PathPoint> continueFrom;
    // Workers that compute the path and each row's orientation (the result does
    // not depend on it).
    int threads = 1;
    // Set from another thread, stops the path and orientation within a block of rows
    // (GeometryCancelled).
    const std::atomic<bool>* cancel = nullptr;
};

// Thrown by WellGeometry's constructor when GeometryOptions::cancel stopped it.
class GeometryCancelled : public std::runtime_error {
public:
    GeometryCancelled() : std::runtime_error("building the well geometry was cancelled") {}
};

// Two pads measure one diameter: their section is drawn and analysed as the
// circle through both, from this many knots (a 200 mm circle seen from 10 mm
// off its centre: equivalent diameter within 0.05 mm of the exact 48-gon's,
// WellAnalysisTest.TwoPadsAreTheCircleThroughBothCentredHalfWay).
constexpr int kTwoPadKnots = 8;
// Spline knots per section for a tool of `armCount` arms.
int sectionKnotCount(int armCount);
// The kTwoPadKnots radii, from the tool axis at equal angles from arm 1, of the
// circle through two opposite pads at radii r1 and r2.
void twoPadCircle(double r1_mm, double r2_mm, double* knots);

// The well's path, section orientation and segment layout, computed once from a
// section table (section frames are computed from them when asked); segment meshes are built on
// demand (a worker can build them in any order and on any thread: this class is immutable after
// construction).
class WellGeometry {
public:
    WellGeometry(std::shared_ptr<const io::SectionTable> table, const GeometryOptions& options);

    const io::SectionTable& table() const { return *m_table; }
    const GeometryOptions& options() const { return m_options; }
    const std::vector<PathPoint>& path() const { return m_placed->path; }
    // A path shared with whoever outlives this geometry (the analysis reads its sections'
    // positions from it): the same vector as path().
    std::shared_ptr<const std::vector<PathPoint>> sharedPath() const {
        return {m_placed, &m_placed->path};
    }
    // A row's section frame, computed when asked from the row's path direction and its P1AZ or
    // RB (as orientation() says): bit for bit the frame a stored one would be, without the 72
    // bytes a row that storing it costs (docs/architecture.md, "Memory per well").
    SectionFrame frame(std::size_t row) const;
    std::size_t segmentCount() const { return m_placed->segments.size(); }
    std::pair<std::size_t, std::size_t> segmentRows(std::size_t segment) const {
        return m_placed->segments[segment];
    }

    // The same well drawn another way (radial exaggeration, wall colours): shares this
    // geometry's table, path, orientation and segments, so a new look costs no read and no
    // placement. `colouring` (null: departure from bit size) must have a value per row.
    WellGeometry restyled(double radialExaggeration,
                          std::shared_ptr<const WallColouring> colouring) const;

    // The same well held by about `maxRows` of its rows (every k-th, the first and the last),
    // each placed, oriented and marked measured exactly as here, its segments cut anew and
    // coloured by departure from bit size (the colouring is not carried): what a field picture
    // keeps of a well for its labels, framing and scale once its nodes are built, the rows read
    // again when the camera wants finer levels (docs/architecture.md, "A field held lean").
    // The whole well when it has no more rows than that.
    WellGeometry sampled(std::size_t maxRows) const;
    // The same well held by `rows` of its rows (increasing, each at most once, the first and
    // the last among them), as sampled(maxRows) holds it. Its segments are this geometry's
    // when every segment's first and last rows are among `rows` (a segment ends on the last
    // row within its length, and no row between is held to end it sooner).
    WellGeometry sampled(const std::vector<std::size_t>& rows) const;

    // Whether a row has enough valid arms to define its section's shape; a
    // row without is drawn as a gap and analysed as no_data.
    bool measured(std::size_t row) const { return m_placed->measured[row] != 0; }
    std::size_t measuredRows() const { return m_placed->measuredRows; }
    // The runs of rows without data, in depth order.
    std::vector<NoDataInterval> noDataIntervals() const;

    // Radii of a row with missing or non-positive arms filled from their
    // neighbours in the section (NaN-free; millimetres) into `out` (armCount
    // values); returns how many arms were repaired. A row without data
    // (measured() false) gets meaningless radii: callers skip it.
    int repairRadii(std::size_t row, double* out) const;

    // The spline knots of a row's section: knotCount() radii at equal angles
    // clockwise from arm 1, the repaired pads themselves for three or more arms;
    // for two pads (one diameter) the circle through both, centred half-way
    // between them (docs/conventions.md). Returns how many arms were repaired.
    int knotCount() const { return sectionKnotCount(m_table->armCount); }
    int sectionKnots(std::size_t row, double* out) const;

    // Which reading placed arm 1 on each row.
    enum class Orientation : unsigned char { PadAzimuth, RelativeBearing, Unoriented };
    Orientation orientation(std::size_t row) const { return m_placed->orientation[row]; }

    // False when the log is inclined but gives no hole azimuth and no survey
    // replaces it: the path then leans north only because an azimuth is needed
    // to draw it, and north, east and azimuth are not known.
    bool holeAzimuthKnown() const {
        return !m_options.survey.empty() ||
               m_table->holeAzimuth != io::SectionTable::HoleAzimuth::Unknown;
    }

    // Gauge radius of a row, millimetres: half the bit size, or inside casing half the casing's
    // nominal inner diameter (io::casingAt); NaN when unknown.
    double bitRadius_mm(std::size_t row) const;

    // The level-of-detail meshes of one segment, every level (reconstruction/mesh/lod_levels.h
    // builds them; buildSegmentLevels builds some).
    SegmentMesh buildSegment(std::size_t segment) const;
    // The closed spline of the full-detail level, shared by every segment.
    const PeriodicSplineSampler& sampler() const { return m_sampler; }

    // Tool-axis position of a row in the analysis frame (metres), wellhead offset included.
    Ned centre(std::size_t row) const;

private:
    void markMeasuredRows();
    void computePathAndOrientation();
    bool cancelled() const;
    void cutSegments();
    // Also writes each row's unit tangent (north, east, down) to tangents[row].
    void computeSteps(std::size_t first, std::size_t last, double inc, double azi,
                      glm::dvec3* tangents);
    void computeOrientation(std::size_t first, std::size_t last);

    // What the constructor computes, shared (never changed after) by restyled copies.
    struct Placement {
        std::vector<PathPoint> path;
        std::vector<Orientation> orientation;
        std::vector<unsigned char> measured;
        std::size_t measuredRows = 0;
        std::vector<std::pair<std::size_t, std::size_t>> segments;
    };

    std::shared_ptr<const io::SectionTable> m_table;
    GeometryOptions m_options;
    std::shared_ptr<Placement> m_placed;
    PeriodicSplineSampler m_sampler;
};

// The rows sampled(maxRows) keeps of `rows` rows when it samples: every k-th (k = rows /
// maxRows, at least 1), and the last.
std::vector<std::size_t> everyKthRow(std::size_t rows, std::size_t maxRows);

// The path as a line to draw: the centres (scene frame) of the rows about `spacing_m` apart
// from the first row deeper than `after_m`, and the last row.
std::vector<glm::vec3> pathLine(const WellGeometry& geometry, double spacing_m = 1.0,
                                double after_m = -1.0e300);
// The points of `line` that a line through them alone keeps within `tolerance` (scene units)
// of every point left out, the first and last always: each stretch is split at its point
// furthest from the chord between its ends while that point is further than the tolerance
// (Douglas and Peucker, 1973). `error`, when given, gets the largest distance left out.
std::vector<std::size_t> simplifiedLine(const std::vector<glm::vec3>& line, float tolerance,
                                        float* error = nullptr);
// The rows pathLine draws: a copy of the geometry that holds them draws the same line.
std::vector<std::size_t> pathLineRows(const WellGeometry& geometry, double spacing_m = 1.0,
                                      double after_m = -1.0e300);

}  // namespace caliper3d::reconstruction

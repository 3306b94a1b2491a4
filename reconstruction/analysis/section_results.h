#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>
#include <utility>
#include <vector>

#include "reconstruction/analysis/borehole_classifier.h"
#include "reconstruction/parallel/fill_array.h"
#include "reconstruction/path/minimum_curvature.h"

namespace caliper3d::reconstruction {

// Everything the report says about one section (analysis frame: north, east,
// TVD down from the wellhead, metres; wellhead offset not included).
struct SectionResult {
    double md_m = 0.0, tvd_m = 0.0, north_m = 0.0, east_m = 0.0;
    double inc_deg = 0.0, azi_deg = 0.0, dls_degPer30m = 0.0;
    double bit_mm = 0.0;  // gauge used (NaN when unknown)
    double area_mm2 = 0.0, equivalentDiameter_mm = 0.0;
    double dmin_mm = 0.0, dmax_mm = 0.0, ellipticity = 1.0;
    double majorAzimuth_deg = 0.0;  // world azimuth of the major axis, [0, 180); NaN if vertical
    double majorFromHighSide_deg = 0.0;    // clockwise from the high side, [0, 180)
    double centreOffset_mm = 0.0;          // tool axis to hole centre
    double centreOffsetAzimuth_deg = 0.0;  // direction from tool axis to hole centre, [0, 360)
    int repairedArms = 0;                  // arms interpolated on this section
    // NoData: too few valid arms; every measurement above from area_mm2 on is NaN.
    BoreholeClass cls = BoreholeClass::InGauge;
};

// What the analysis measured on one section: SectionResult without the position and direction
// the well's path holds already, its measurements in single precision (48 bytes a row where a
// SectionResult is 144; docs/architecture.md, "Memory per well"). Floats are 0.00003 mm apart
// at a diameter of 500 mm, 0.016 mm2 at an area of 200,000 mm2 and 0.00003 degrees at 360,
// far below the 0.01 mm, 0.1 mm2 and 0.01 degrees the report prints. The gauge stays as the
// log or the casing program gives it.
struct SectionMeasure {
    double bit_mm = 0.0;
    float area_mm2 = 0.0F, equivalentDiameter_mm = 0.0F;
    float dmin_mm = 0.0F, dmax_mm = 0.0F, ellipticity = 1.0F;
    float majorAzimuth_deg = 0.0F, majorFromHighSide_deg = 0.0F;
    float centreOffset_mm = 0.0F, centreOffsetAzimuth_deg = 0.0F;
    std::uint16_t repairedArms = 0;  // at most io::kMaxArms - 1 on a measured section
    BoreholeClass cls = BoreholeClass::InGauge;
};

// The per-section results of a well, one per row in depth order, stored compactly
// (docs/architecture.md, "Memory per well"): each row's measurements, and a share of the well's
// path for where the section is. Reading a row assembles its SectionResult; the store itself
// holds no copy of MD, TVD, north, east, inclination, azimuth or dogleg severity.
class SectionResults {
public:
    SectionResults() = default;
    // Room for one measure per path point, each to be set once (set()) before it is read.
    // `azimuthKnown` false: the log is inclined without a hole azimuth, and the results give
    // no azimuth, and no north nor east wherever the path has leaned (docs/conventions.md).
    SectionResults(std::shared_ptr<const std::vector<PathPoint>> path, bool azimuthKnown);

    std::size_t size() const { return m_measures.size(); }
    bool empty() const { return m_measures.empty(); }

    // Row i's result, assembled from its path point and its measure.
    SectionResult operator[](std::size_t i) const;
    SectionResult front() const { return (*this)[0]; }
    SectionResult back() const { return (*this)[size() - 1]; }
    // Row i's measured depth, without assembling the rest.
    double md_m(std::size_t i) const { return (*m_path)[i].md; }
    // The well's path the rows are on (one point a row; empty when the store is).
    const std::vector<PathPoint>& path() const { return m_path ? *m_path : kNoPath; }

    // Constructs row i's measure (once, before it is read).
    void set(std::size_t i, const SectionMeasure& m) { m_measures.set(i, m); }
    const SectionMeasure& measure(std::size_t i) const { return m_measures[i]; }
    SectionMeasure& measure(std::size_t i) { return m_measures[i]; }
    SectionMeasure* data() { return m_measures.data(); }
    const SectionMeasure* data() const { return m_measures.data(); }

    // Iterates the rows' results by value.
    class Iterator {
    public:
        using iterator_category = std::input_iterator_tag;
        using value_type = SectionResult;
        using difference_type = std::ptrdiff_t;
        using pointer = void;
        using reference = SectionResult;

        Iterator(const SectionResults* results, std::size_t row) : m_results(results), m_row(row) {}
        SectionResult operator*() const { return (*m_results)[m_row]; }
        Iterator& operator++() {
            ++m_row;
            return *this;
        }
        Iterator operator++(int) {
            Iterator before = *this;
            ++m_row;
            return before;
        }
        bool operator==(const Iterator& other) const { return m_row == other.m_row; }
        bool operator!=(const Iterator& other) const { return m_row != other.m_row; }

    private:
        const SectionResults* m_results;
        std::size_t m_row;
    };
    Iterator begin() const { return {this, 0}; }
    Iterator end() const { return {this, size()}; }

private:
    static inline const std::vector<PathPoint> kNoPath{};
    std::shared_ptr<const std::vector<PathPoint>> m_path;
    FillArray<SectionMeasure> m_measures;
    bool m_azimuthKnown = true;
};

}  // namespace caliper3d::reconstruction

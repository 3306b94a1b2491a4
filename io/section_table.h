#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "io/casing_string.h"

namespace caliper3d::io {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Caliper tools read: from two pads (one diameter) to 256 fingers.
inline constexpr int kMinArms = 2;
inline constexpr int kMaxArms = 256;

// A curve the log carries beside the caliper (gamma ray, resistivity, ...),
// kept in its own unit for colouring and export.
struct ExtraCurve {
    std::string mnemonic;
    std::string unit;
    std::string description;
    std::vector<double> values;  // one per row, NaN where null
};

// One caliper log as read from a file, in the product's internal units:
// depths in metres (measured depth along the hole), radii in millimetres
// (tool axis to wall), angles in degrees. Struct of arrays; every non-empty
// vector has one value per row. Optional curves are empty when the log lacks
// them; a missing value inside a present curve is NaN.
struct SectionTable {
    std::string source;    // file the table came from (for messages)
    std::string wellName;  // the log's well name (LAS ~Well WELL), empty when it gives none
    // The units the file wrote its depth and its caliper curves in ("M", "FT", "IN", "MM"...;
    // empty when it wrote none): the table itself holds metres and millimetres.
    std::string fileDepthUnit, fileCaliperUnit;
    int armCount = 0;  // radii per row

    std::vector<double> depth_m;
    std::vector<double> radius_mm;   // row-major: armCount values per row
    std::vector<double> p1az_deg;    // azimuth of arm 1 from north, clockwise
    std::vector<double> devi_deg;    // inclination, 0 = vertical down
    std::vector<double> hazi_deg;    // hole azimuth from north, clockwise
    std::vector<double> rb_deg;      // relative bearing of arm 1 from the high side
    std::vector<double> bitSize_mm;  // bit size per row (from a parameter or a curve)
    std::vector<ExtraCurve> extraCurves;
    // Where hole_azimuth came from (docs/conventions.md, "Hole azimuth"):
    // read from the log (or not needed: no HAZI and no inclination), derived
    // from P1AZ and RB by a known tool's convention, or unknown (the log is
    // inclined but gives no azimuth: the path is drawn without a departure and the
    // report leaves what depends on it empty).
    enum class HoleAzimuth : unsigned char { Read, Derived, Unknown };
    HoleAzimuth holeAzimuth = HoleAzimuth::Read;
    // Which north p1az_deg and hazi_deg are from and the declination or grid convergence
    // applied to reach it (docs/conventions.md, "North"), as the report and the window
    // show it; empty when the table has no azimuth curve.
    std::string north;
    // The casing set in the hole (--casing, else the LAS ~Parameter section), shallowest
    // shoe first; empty when neither says (docs/analysis.md, "Cased hole").
    std::vector<CasingString> casing;

    std::size_t rowCount() const { return depth_m.size(); }
    const double* radii(std::size_t row) const { return radius_mm.data() + row * armCount; }
    double* radii(std::size_t row) { return radius_mm.data() + row * armCount; }

    // Appends all rows of `other` (same armCount and same optional curves).
    void append(const SectionTable& other);
    // Appends rows [first, last) of `other`, whose curves match this table's.
    void appendRows(const SectionTable& other, std::size_t first, std::size_t last);
    // Rows [first, last) as a table of their own, with this table's curves (optional and
    // extra), source and hole-azimuth kind.
    SectionTable rows(std::size_t first, std::size_t last) const;
    // Removes every row; the curves present and the extra-curve list stay.
    void clearRows();
    // Keeps the rows listed, in the order listed.
    void keepRows(const std::vector<std::size_t>& rows);
    void reserve(std::size_t rows);
};

}  // namespace caliper3d::io

#pragma once

#include <climits>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "reconstruction/mesh/colour_map.h"

namespace caliper3d::reconstruction {

// What a picture's legend says about the wall's colours (docs/conventions.md, "Colours").
struct ColourLegend {
    std::string title;  // "radius - bit radius", "equivalent diameter", "GR", ...
    std::string unit;   // "mm", "deg/30m", the curve's own unit; empty when none
    ColourMapKind kind = ColourMapKind::Diverging;
    double lo = 0.0, hi = 0.0;  // the values at the map's ends (continuous maps)
    std::string range;          // where [lo, hi] comes from: "fixed", "given", "2-98 percentile"
    std::string note;           // e.g. what stands in for a missing bit size
    std::vector<std::pair<std::string, std::uint32_t>> categories;  // categorical maps
    bool noValue = false;  // some drawn sections have no value: they show kNoValueColour
    // What the centre of a diverging map stands for ("no change"); empty: the bit, or the
    // gauge where a note says what stands in for it.
    std::string centre;
    // What a section without a value means ("not compared: ..."); empty: "no value". A
    // '\n' starts a new line of the legend.
    std::string noValueText;
};

// Values of some rows at each direction round the section (WallColouring::perDirection): a
// row's values at `bins` equal angles clockwise from its own zero, bin b centred at
// (b + 0.5) * 360 / bins degrees from it, and where arm 1 lies from that zero. Stored as
// multiples of `step` (16 bits: a 4 km log at 2.5 mm of 36 bins takes about 130 MB).
inline constexpr std::int16_t kNoDirectionalValue = INT16_MIN;  // a bin without a value
struct DirectionalValues {
    int bins = 36;
    float step = 0.05f;
    std::vector<std::int32_t> slot;    // per row: its values' place, or -1 (the row's own value)
    std::vector<float> arm1Angle_deg;  // per slot: arm 1 clockwise from the bins' zero
    std::vector<std::int16_t> values;  // per slot, `bins` of them
};

// The wall's colour at each point: a departure of the point's radius from a reference
// radius of its row (bit size), or one value per row (a section's diameter, class, a log
// curve...). Rows are those of one well's table. Immutable once made; shared by the
// threads that build meshes.
class WallColouring {
public:
    // Departures (radius - reference, mm) over [lo, hi] on the diverging map, 0 at its
    // centre. A NaN reference colours its row kNoValueColour.
    static WallColouring departure(std::vector<float> referenceRadius_mm, double lo_mm,
                                   double hi_mm, ColourLegend legend);
    // One value per row over [lo, hi] on a continuous map; NaN: kNoValueColour.
    static WallColouring perRow(std::vector<float> values, ColourMapKind kind, double lo, double hi,
                                ColourLegend legend);
    // One category per row: values index legend.categories (NaN: kNoValueColour).
    static WallColouring categories(std::vector<float> values, ColourLegend legend);
    // One value per direction round the rows `directional` holds, one per row elsewhere, over
    // [lo, hi] on a continuous map; NaN: kNoValueColour.
    static WallColouring perDirection(std::vector<float> rowValues, DirectionalValues directional,
                                      ColourMapKind kind, double lo, double hi,
                                      ColourLegend legend);

    // The same colours, described by `legend` (its map and range must be this one's).
    WallColouring withLegend(ColourLegend legend) const;
    // The colours of `rows` only (increasing, each at most once): row i of the copy is
    // rows[i] here, for a geometry that holds those rows (WellGeometry::sampled).
    WallColouring rowsOf(const std::vector<std::size_t>& rows) const;

    std::uint32_t colour(std::size_t row, double radius_mm) const;
    // The colour of the wall point `angleFromArm1_deg` clockwise from arm 1 (about the
    // section's centre); the same as colour(row, radius) unless the colouring is per direction.
    std::uint32_t colour(std::size_t row, double radius_mm, double angleFromArm1_deg) const;
    bool byDirection() const { return m_source == Source::Directional; }
    std::size_t rowCount() const { return m_values.size(); }
    const ColourLegend& legend() const { return m_legend; }

private:
    enum class Source : unsigned char { Departure, Continuous, Categorical, Directional };
    WallColouring(Source source, std::vector<float> values, ColourLegend legend);
    std::uint32_t continuousColour(double value) const;

    Source m_source;
    std::vector<float> m_values;  // reference radius or value, per row
    ColourLegend m_legend;
    std::vector<std::uint32_t> m_categoryColours;
    DirectionalValues m_directional;  // Directional only
};

// Departure from bit size over the fixed range the window starts with (kDepartureRange_mm
// either side of the bit; grey in gauge): the colour of a wall point when a geometry has no
// WallColouring. A NaN bit radius gives kNoValueColour.
inline constexpr double kDepartureRange_mm = 25.0;
std::uint32_t departureColour(double radius_mm, double bitRadius_mm,
                              double lo_mm = -kDepartureRange_mm,
                              double hi_mm = kDepartureRange_mm);

// Where a value falls on [lo, hi] as the map's t; for a diverging map 0 is always at 0.5
// (each side scaled on its own, so a range that is not symmetric keeps the reference grey).
double mapPosition(ColourMapKind kind, double value, double lo, double hi);

}  // namespace caliper3d::reconstruction

#include "reconstruction/mesh/wall_colouring.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace caliper3d::reconstruction {

double mapPosition(ColourMapKind kind, double value, double lo, double hi) {
    if (!std::isfinite(value)) return value;
    if (kind == ColourMapKind::Diverging) {
        if (value >= 0.0) return hi > 0.0 ? 0.5 + 0.5 * std::min(value / hi, 1.0) : 1.0;
        return lo < 0.0 ? 0.5 - 0.5 * std::min(value / lo, 1.0) : 0.0;
    }
    return hi > lo ? (value - lo) / (hi - lo) : 0.5;
}

std::uint32_t departureColour(double radius_mm, double bitRadius_mm, double lo_mm, double hi_mm) {
    const double d = radius_mm - bitRadius_mm;
    if (!std::isfinite(d)) return kNoValueColour;
    return divergingColour(mapPosition(ColourMapKind::Diverging, d, lo_mm, hi_mm));
}

WallColouring::WallColouring(Source source, std::vector<float> values, ColourLegend legend)
    : m_source(source), m_values(std::move(values)), m_legend(std::move(legend)) {
    for (const auto& category : m_legend.categories) m_categoryColours.push_back(category.second);
}

WallColouring WallColouring::departure(std::vector<float> referenceRadius_mm, double lo_mm,
                                       double hi_mm, ColourLegend legend) {
    legend.kind = ColourMapKind::Diverging;
    legend.lo = lo_mm;
    legend.hi = hi_mm;
    return WallColouring(Source::Departure, std::move(referenceRadius_mm), std::move(legend));
}

WallColouring WallColouring::perRow(std::vector<float> values, ColourMapKind kind, double lo,
                                    double hi, ColourLegend legend) {
    legend.kind = kind;
    legend.lo = lo;
    legend.hi = hi;
    return WallColouring(Source::Continuous, std::move(values), std::move(legend));
}

WallColouring WallColouring::categories(std::vector<float> values, ColourLegend legend) {
    legend.kind = ColourMapKind::Categorical;
    return WallColouring(Source::Categorical, std::move(values), std::move(legend));
}

WallColouring WallColouring::perDirection(std::vector<float> rowValues,
                                          DirectionalValues directional, ColourMapKind kind,
                                          double lo, double hi, ColourLegend legend) {
    legend.kind = kind;
    legend.lo = lo;
    legend.hi = hi;
    WallColouring out(Source::Directional, std::move(rowValues), std::move(legend));
    out.m_directional = std::move(directional);
    return out;
}

WallColouring WallColouring::withLegend(ColourLegend legend) const {
    WallColouring out = *this;
    out.m_legend = std::move(legend);
    return out;
}

WallColouring WallColouring::rowsOf(const std::vector<std::size_t>& rows) const {
    WallColouring out(m_source, {}, m_legend);
    out.m_values.reserve(rows.size());
    for (const std::size_t row : rows) out.m_values.push_back(m_values[row]);
    if (m_source != Source::Directional) return out;
    // Only the slots of the rows kept, renumbered.
    const DirectionalValues& from = m_directional;
    DirectionalValues& to = out.m_directional;
    to.bins = from.bins;
    to.step = from.step;
    const auto bins = static_cast<std::size_t>(from.bins);
    for (const std::size_t row : rows) {
        const std::int32_t slot = row < from.slot.size() ? from.slot[row] : -1;
        if (slot < 0) {
            to.slot.push_back(-1);
            continue;
        }
        const auto s = static_cast<std::size_t>(slot);
        to.slot.push_back(static_cast<std::int32_t>(to.arm1Angle_deg.size()));
        to.arm1Angle_deg.push_back(from.arm1Angle_deg[s]);
        to.values.insert(to.values.end(),
                         from.values.begin() + static_cast<std::ptrdiff_t>(s * bins),
                         from.values.begin() + static_cast<std::ptrdiff_t>((s + 1) * bins));
    }
    return out;
}

std::uint32_t WallColouring::continuousColour(double v) const {
    if (!std::isfinite(v)) return kNoValueColour;
    return m_legend.kind == ColourMapKind::Diverging
               ? divergingColour(mapPosition(m_legend.kind, v, m_legend.lo, m_legend.hi))
               : sequentialColour(mapPosition(m_legend.kind, v, m_legend.lo, m_legend.hi));
}

std::uint32_t WallColouring::colour(std::size_t row, double radius_mm,
                                    double angleFromArm1_deg) const {
    if (m_source != Source::Directional || row >= m_directional.slot.size())
        return colour(row, radius_mm);
    const std::int32_t slot = m_directional.slot[row];
    if (slot < 0 || !std::isfinite(angleFromArm1_deg)) return colour(row, radius_mm);
    const auto s = static_cast<std::size_t>(slot);
    const int bins = m_directional.bins;
    // Bin b is centred at (b + 0.5) * 360 / bins from the bins' zero; between two centres the
    // value is interpolated, so the wall shows no steps of the bins' width.
    double a = std::fmod(angleFromArm1_deg + m_directional.arm1Angle_deg[s], 360.0);
    if (a < 0.0) a += 360.0;
    const double position = a * bins / 360.0 - 0.5;  // in (-0.5, bins - 0.5)
    const double below = std::floor(position);
    const double t = position - below;
    const std::int16_t* values = &m_directional.values[s * static_cast<std::size_t>(bins)];
    const auto at = [&](double bin) {
        const int b = (static_cast<int>(bin) + bins) % bins;
        return values[static_cast<std::size_t>(b)];
    };
    const std::int16_t q0 = at(below), q1 = at(below + 1.0);
    if (q0 == kNoDirectionalValue || q1 == kNoDirectionalValue) return kNoValueColour;
    const double v =
        (static_cast<double>(q0) + t * (static_cast<double>(q1) - q0)) * m_directional.step;
    return continuousColour(v);
}

std::uint32_t WallColouring::colour(std::size_t row, double radius_mm) const {
    const double v = m_values[row];
    switch (m_source) {
        case Source::Departure:
            return departureColour(radius_mm, v, m_legend.lo, m_legend.hi);
        case Source::Continuous:
        case Source::Directional:
            return continuousColour(v);
        case Source::Categorical: {
            if (!(v >= 0.0) || static_cast<std::size_t>(v) >= m_categoryColours.size())
                return kNoValueColour;
            return m_categoryColours[static_cast<std::size_t>(v)];
        }
    }
    return kNoValueColour;
}

}  // namespace caliper3d::reconstruction

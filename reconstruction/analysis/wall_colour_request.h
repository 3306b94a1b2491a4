#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "reconstruction/analysis/well_analysis.h"
#include "reconstruction/mesh/wall_colouring.h"

namespace caliper3d::reconstruction {

// What to colour the wall by (`--colour-by NAME`, the window's "Colour by" box) and over
// which range (`--colour-range LO,HI`; unset: the quantity's default, docs/conventions.md,
// "Colours").
struct ColourRequest {
    std::string quantity = "departure";
    std::optional<std::pair<double, double>> range;
    // For "change" (`--compare-with RUN`): the other run of the same well the drawn one is
    // compared with (docs/analysis.md, "Colour by change"); the window names it itself.
    std::string compareWith;
};
// The quantity of a colouring by change against another run (run_change.h).
inline constexpr const char* kChangeQuantity = "change";
inline bool operator==(const ColourRequest& a, const ColourRequest& b) {
    return a.quantity == b.quantity && a.range == b.range && a.compareWith == b.compareWith;
}
inline bool operator!=(const ColourRequest& a, const ColourRequest& b) {
    return !(a == b);
}

// The report's per-section values a colouring may need, kept compact (three floats a row
// instead of the whole analysis), so a window computes them once and recolours from them.
struct SectionValues {
    std::vector<float> equivalentDiameter_mm;  // NaN where no data
    std::vector<float> ellipticity;
    std::vector<float> cls;          // BoreholeClass as a number; NaN where no data
    double gauge_mm = 0.0;           // the gauge the classes were found against (first row's)
    bool gaugeFromSections = false;  // no bit size: the median equivalent diameter
};
SectionValues sectionValues(const WellGeometry& geometry, const AnalysisOptions& analysis = {});
// The same from a well's analysis already made (the window analyses each well once).
SectionValues sectionValues(const WellAnalysis& analysis);

// The quantities a well can be coloured by: departure, diameter, ellipticity, class, dls,
// then every extra curve of its log (gamma ray, resistivity...) by its mnemonic.
std::vector<std::string> colourQuantities(const io::SectionTable& table);

// The colouring of `geometry`'s wall that `request` asks for. Section values (diameter,
// ellipticity, class) are the report's own (analyseWell with `analysis`); without a bit size
// departures are measured from the median equivalent diameter, as the report does, and the
// legend says so. Throws std::invalid_argument naming the valid quantities for an unknown
// one, or for a range that is empty or (for departures) does not hold 0.
// `values`: the well's sectionValues when already computed (null: computed here when needed).
// "change" needs the other run: it is made by changeColouring (run_change.h), and here throws
// std::invalid_argument saying so.
std::shared_ptr<const WallColouring> makeWallColouring(const WellGeometry& geometry,
                                                       const ColourRequest& request,
                                                       const SectionValues* values = nullptr,
                                                       const AnalysisOptions& analysis = {});

// The wall colourings `request` asks for, one per well, sharing one colour range so a colour
// means the same value in each (the union of their own ranges, when it comes from the
// data). Throws std::invalid_argument as makeWallColouring does. `values`: each well's
// sectionValues where known (null or missing: computed when the quantity needs them).
std::vector<std::shared_ptr<const WallColouring>> wallColourings(
    const std::vector<std::shared_ptr<const WellGeometry>>& wells, const ColourRequest& request,
    const std::vector<const SectionValues*>& values = {});

// The two steps of wallColourings, for a caller that holds one well at a time (a field held
// lean, app/scene_assembly.cpp): from each well's own colouring's legend, the request every
// well is then coloured with (their ranges' union, for a sequential quantity whose range comes
// from the data; nullopt: each keeps its own colouring); and one well's colouring under it,
// its legend's range saying it spans all `wells` wells.
std::optional<ColourRequest> sharedColourRequest(const std::vector<ColourLegend>& own,
                                                 const ColourRequest& request);
std::shared_ptr<const WallColouring> sharedWallColouring(const WellGeometry& well,
                                                         const ColourRequest& shared,
                                                         const ColourLegend& own, std::size_t wells,
                                                         const SectionValues* values = nullptr);
// The same from a well's own colouring (made with the request the field shares, before its
// range was shared), for a caller that holds only some of the well's rows (its colouring's
// WallColouring::rowsOf): the colours of `own`'s values over the shared range.
std::shared_ptr<const WallColouring> sharedWallColouring(const WallColouring& own,
                                                         const ColourRequest& shared,
                                                         std::size_t wells);

// The report's classes, from the Okabe-Ito palette (told apart with any colour vision).
std::uint32_t classColour(BoreholeClass c);

// The p-th fraction (0-1) of the finite `values`, nearest rank; NaN when none is finite.
double robustPercentile(std::vector<float> values, double p);

}  // namespace caliper3d::reconstruction

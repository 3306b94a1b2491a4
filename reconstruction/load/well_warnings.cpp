#include "reconstruction/load/well_warnings.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace caliper3d::reconstruction {

namespace {

void warnNoData(const WellGeometry& g, io::Diagnostics& d) {
    const int arms = g.table().armCount;
    const int needed = minValidArms(arms, g.options().minValidArmFraction);
    for (const NoDataInterval& gap : g.noDataIntervals())
        d.warn(g.table().source, 0,
               "no caliper data over " + describeNoDataInterval(gap) + ": fewer than " +
                   std::to_string(needed) + " of " + std::to_string(arms) +
                   " arms valid; class no_data, drawn as a gap");
}

void warnRepaired(const WellGeometry& g, std::size_t arms, std::size_t sections,
                  io::Diagnostics& d) {
    if (sections == 0) return;
    d.warn(g.table().source, 0,
           std::to_string(arms) + " arms interpolated on " + std::to_string(sections) +
               " sections (missing, closed or beyond reach)");
}

}  // namespace

void warnGeometry(const WellGeometry& g, io::Diagnostics& d) {
    warnNoData(g, d);
    std::size_t arms = 0, sections = 0;
    std::vector<double> radii(static_cast<std::size_t>(g.table().armCount));
    for (std::size_t row = 0; row < g.table().rowCount(); ++row) {
        if (!g.measured(row)) continue;
        const int repaired = g.repairRadii(row, radii.data());
        arms += static_cast<std::size_t>(repaired);
        sections += repaired > 0;
    }
    warnRepaired(g, arms, sections, d);
}

void warnAnalysis(const WellGeometry& g, const WellAnalysis& a, io::Diagnostics& d) {
    warnNoData(g, d);
    warnRepaired(g, a.repairedArms, a.repairedSections, d);
    const std::string& file = g.table().source;
    if (a.unorientedSections > 0)
        d.warn(file, 0,
               std::to_string(a.unorientedSections) +
                   " sections without a pad-1 azimuth or relative bearing: orientation "
                   "unknown, their azimuths are left empty");
    for (const NoDataInterval& gap : a.armsNotOpen)
        d.warn(file, 0,
               "arms not open over " + describeNoDataInterval(gap) +
                   ": the largest diameter stays far below gauge (docs/analysis.md, \"Arms not "
                   "open\"); class no_data, not undergauge");
    for (const CasingCheck& c : a.casing) {
        // Only a casing the log reaches into (its shoe at or below the first section).
        if (std::isfinite(c.casing.innerDiameter_mm) || a.sections.empty() ||
            !(c.casing.bottom_m >= a.sections[0].md_m))
            continue;
        char shoe[32];
        std::snprintf(shoe, sizeof shoe, "%.2f", c.casing.bottom_m);
        d.warn(file, 0,
               std::string("casing to ") + shoe +
                   " m: nominal inner diameter unknown (give --casing BOTTOM,SIZE,WEIGHT or ID); "
                   "its sections are cased, without a calibration check");
    }
    if (a.bitSizeFromSections)
        d.warn(file, 0, "no bit size given: the median equivalent diameter is used as gauge");
}

}  // namespace caliper3d::reconstruction

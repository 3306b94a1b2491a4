#include "reconstruction/analysis/wall_colour_request.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <tuple>

namespace caliper3d::reconstruction {

namespace {

constexpr float kNaNf = std::numeric_limits<float>::quiet_NaN();

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

std::string millimetres(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f mm", v);
    return text;
}

// The range a continuous quantity is drawn over: the given one, or the 2nd to 98th
// percentile of the values of the measured sections (a few extreme sections do not wash
// the rest into one colour); a range of one value is widened so the map still has ends.
std::pair<double, double> rangeOf(const std::vector<float>& values, const WellGeometry& g,
                                  const ColourRequest& request, ColourLegend& legend) {
    if (request.range) {
        legend.range = "given";
        return *request.range;
    }
    std::vector<float> measured;
    measured.reserve(values.size());
    for (std::size_t row = 0; row < values.size(); ++row)
        if (g.measured(row)) measured.push_back(values[row]);
    double lo = robustPercentile(measured, 0.02), hi = robustPercentile(std::move(measured), 0.98);
    legend.range = "2-98 percentile";
    if (!std::isfinite(lo) || !std::isfinite(hi)) return {0.0, 1.0};
    if (hi - lo < 1e-9) {
        const double pad = std::max(std::abs(lo) * 0.01, 1e-3);
        lo -= pad;
        hi += pad;
    }
    return {lo, hi};
}

bool anyNaNWhereMeasured(const std::vector<float>& values, const WellGeometry& g) {
    for (std::size_t row = 0; row < values.size(); ++row)
        if (g.measured(row) && !std::isfinite(values[row])) return true;
    return false;
}

}  // namespace

double robustPercentile(std::vector<float> values, double p) {
    values.erase(
        std::remove_if(values.begin(), values.end(), [](float v) { return !std::isfinite(v); }),
        values.end());
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    const auto k = static_cast<std::size_t>(
        std::lround(std::clamp(p, 0.0, 1.0) * static_cast<double>(values.size() - 1)));
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
    return values[k];
}

std::uint32_t classColour(BoreholeClass c) {
    switch (c) {
        case BoreholeClass::InGauge:
            return 0xC8C8C8FFu;  // light grey: nothing to see
        case BoreholeClass::Undergauge:
            return 0x0072B2FFu;  // blue
        case BoreholeClass::Washout:
            return 0xD55E00FFu;  // vermillion
        case BoreholeClass::Breakout:
            return 0xE69F00FFu;  // orange
        case BoreholeClass::Keyseat:
            return 0xCC79A7FFu;  // reddish purple
        case BoreholeClass::Cased:
            return 0x4D4D4DFFu;  // dark grey: steel
        case BoreholeClass::NoData:
            break;
    }
    return kNoValueColour;
}

SectionValues sectionValues(const WellGeometry& g, const AnalysisOptions& analysis) {
    return sectionValues(analyseWell(g, analysis));
}

SectionValues sectionValues(const WellAnalysis& a) {
    const std::size_t rows = a.sections.size();
    SectionValues out;
    out.equivalentDiameter_mm.resize(rows);
    out.ellipticity.resize(rows);
    out.cls.resize(rows);
    for (std::size_t row = 0; row < rows; ++row) {
        const SectionResult& r = a.sections[row];
        out.equivalentDiameter_mm[row] = static_cast<float>(r.equivalentDiameter_mm);
        out.ellipticity[row] = static_cast<float>(r.ellipticity);
        out.cls[row] = r.cls == BoreholeClass::NoData ? kNaNf : static_cast<float>(r.cls);
    }
    out.gauge_mm = rows > 0 ? a.sections[0].bit_mm : kNaNf;
    out.gaugeFromSections = a.bitSizeFromSections;
    return out;
}

std::vector<std::string> colourQuantities(const io::SectionTable& table) {
    std::vector<std::string> names{"departure", "diameter", "ellipticity", "class", "dls"};
    for (const io::ExtraCurve& curve : table.extraCurves) names.push_back(curve.mnemonic);
    return names;
}

namespace {

// The wall coloured by the departure of each radius from the bit's (or, with no bit size, the
// gauge's: the median equivalent diameter, as the report takes it).
std::shared_ptr<const WallColouring> departureColouring(
    const WellGeometry& g, const ColourRequest& request,
    const std::function<const SectionValues&()>& analysed) {
    const std::size_t rows = g.table().rowCount();
    ColourLegend legend;
    std::vector<float> values(rows, kNaNf);
    legend.title = "radius - bit radius";
    legend.unit = "mm";
    bool anyBit = false;
    for (std::size_t row = 0; row < rows; ++row) {
        values[row] = static_cast<float>(g.bitRadius_mm(row));
        anyBit = anyBit || std::isfinite(values[row]);
    }
    if (!anyBit) {
        // As the report: the median equivalent diameter stands in for the bit size.
        const double gauge = analysed().gauge_mm;
        std::fill(values.begin(), values.end(), static_cast<float>(gauge / 2.0));
        legend.title = "radius - gauge radius";
        legend.note = "no bit size: gauge is the median equivalent diameter, " + millimetres(gauge);
    }
    double lo = -kDepartureRange_mm, hi = kDepartureRange_mm;
    legend.range = "fixed";
    if (request.range) {
        std::tie(lo, hi) = *request.range;
        if (!(lo < 0.0 && hi > 0.0))
            throw std::invalid_argument(
                "--colour-range: departures are drawn either side of the bit size, so LO "
                "must be below 0 and HI above it");
        legend.range = "given";
    }
    legend.noValue = anyNaNWhereMeasured(values, g);
    return std::make_shared<const WallColouring>(
        WallColouring::departure(std::move(values), lo, hi, std::move(legend)));
}

// The wall coloured by each section's class, the casing's colour in the legend where cased.
std::shared_ptr<const WallColouring> classColouring(const WellGeometry& g, const SectionValues& a) {
    ColourLegend legend;
    legend.title = "class";
    for (int c = 0; c <= static_cast<int>(BoreholeClass::Keyseat); ++c) {
        const auto cls = static_cast<BoreholeClass>(c);
        legend.categories.emplace_back(std::string(className(cls)), classColour(cls));
    }
    std::vector<float> values = a.cls;
    // The casing's own colour, in the legend of a well that has cased sections.
    const auto cased = static_cast<float>(BoreholeClass::Cased);
    if (std::find(values.begin(), values.end(), cased) != values.end())
        legend.categories.emplace_back(std::string(className(BoreholeClass::Cased)),
                                       classColour(BoreholeClass::Cased));
    if (a.gaugeFromSections)
        legend.note =
            "no bit size: gauge is the median equivalent diameter, " + millimetres(a.gauge_mm);
    legend.noValue = anyNaNWhereMeasured(values, g);
    return std::make_shared<const WallColouring>(
        WallColouring::categories(std::move(values), std::move(legend)));
}

}  // namespace

std::shared_ptr<const WallColouring> makeWallColouring(const WellGeometry& g,
                                                       const ColourRequest& request,
                                                       const SectionValues* known,
                                                       const AnalysisOptions& analysis) {
    const io::SectionTable& t = g.table();
    const std::size_t rows = t.rowCount();
    const std::string name = lower(request.quantity);
    if (request.range && !(request.range->first < request.range->second))
        throw std::invalid_argument("--colour-range: LO must be below HI");

    if (name == kChangeQuantity)
        throw std::invalid_argument(
            t.source + ": colouring by change needs the other run of the well: --compare-with RUN");
    const io::ExtraCurve* curve = nullptr;
    for (const io::ExtraCurve& c : t.extraCurves)
        if (lower(c.mnemonic) == name) curve = &c;
    const bool valid = curve || name == "departure" || name == "diameter" ||
                       name == "ellipticity" || name == "class" || name == "dls";
    if (!valid)
        throw std::invalid_argument(t.source + ": cannot colour by '" + request.quantity +
                                    "': this well can be coloured by " +
                                    joined(colourQuantities(t)));

    ColourLegend legend;
    std::vector<float> values(rows, kNaNf);
    std::optional<SectionValues> computed;
    auto analysed = [&]() -> const SectionValues& {
        if (known) return *known;
        if (!computed) computed = sectionValues(g, analysis);
        return *computed;
    };

    if (name == "departure") return departureColouring(g, request, analysed);

    if (name == "dls") {
        legend.title = "dogleg severity";
        legend.unit = "deg/30m";
        for (std::size_t row = 0; row < rows; ++row)
            values[row] = static_cast<float>(g.path()[row].dls_degPer30m);
    } else if (curve) {
        legend.title = curve->mnemonic;
        legend.unit = curve->unit;
        if (!curve->description.empty()) legend.note = curve->description;
        for (std::size_t row = 0; row < rows && row < curve->values.size(); ++row)
            values[row] = static_cast<float>(curve->values[row]);
    } else {
        const SectionValues& a = analysed();
        if (name == "class") return classColouring(g, a);
        const bool diameter = name == "diameter";
        legend.title = diameter ? "equivalent diameter" : "ellipticity (dmax / dmin)";
        legend.unit = diameter ? "mm" : "";
        values = diameter ? a.equivalentDiameter_mm : a.ellipticity;
    }
    const auto [lo, hi] = rangeOf(values, g, request, legend);
    legend.noValue = anyNaNWhereMeasured(values, g);
    return std::make_shared<const WallColouring>(WallColouring::perRow(
        std::move(values), ColourMapKind::Sequential, lo, hi, std::move(legend)));
}

std::optional<ColourRequest> sharedColourRequest(const std::vector<ColourLegend>& own,
                                                 const ColourRequest& request) {
    if (own.size() < 2 || request.range || own.front().kind != ColourMapKind::Sequential)
        return std::nullopt;
    double lo = own.front().lo, hi = own.front().hi;
    for (const ColourLegend& legend : own) {
        lo = std::min(lo, legend.lo);
        hi = std::max(hi, legend.hi);
    }
    ColourRequest shared = request;
    shared.range = std::make_pair(lo, hi);
    return shared;
}

std::shared_ptr<const WallColouring> sharedWallColouring(const WellGeometry& well,
                                                         const ColourRequest& shared,
                                                         const ColourLegend& own, std::size_t wells,
                                                         const SectionValues* values) {
    auto colouring = makeWallColouring(well, shared, values);
    ColourLegend legend = colouring->legend();
    legend.range = own.range + ", over all " + std::to_string(wells) + " wells";
    return std::make_shared<const WallColouring>(colouring->withLegend(std::move(legend)));
}

std::shared_ptr<const WallColouring> sharedWallColouring(const WallColouring& own,
                                                         const ColourRequest& shared,
                                                         std::size_t wells) {
    ColourLegend legend = own.legend();
    if (shared.range) std::tie(legend.lo, legend.hi) = *shared.range;
    legend.range += ", over all " + std::to_string(wells) + " wells";
    return std::make_shared<const WallColouring>(own.withLegend(std::move(legend)));
}

std::vector<std::shared_ptr<const WallColouring>> wallColourings(
    const std::vector<std::shared_ptr<const WellGeometry>>& wells, const ColourRequest& request,
    const std::vector<const SectionValues*>& values) {
    auto valuesOf = [&values](std::size_t w) { return w < values.size() ? values[w] : nullptr; };
    std::vector<std::shared_ptr<const WallColouring>> out;
    std::vector<ColourLegend> own;
    for (std::size_t w = 0; w < wells.size(); ++w) {
        out.push_back(makeWallColouring(*wells[w], request, valuesOf(w)));
        own.push_back(out.back()->legend());
    }
    const std::optional<ColourRequest> shared = sharedColourRequest(own, request);
    if (!shared) return out;
    for (std::size_t w = 0; w < wells.size(); ++w)
        out[w] = sharedWallColouring(*wells[w], *shared, own[w], wells.size(), valuesOf(w));
    return out;
}

}  // namespace caliper3d::reconstruction

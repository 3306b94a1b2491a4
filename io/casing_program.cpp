#include "io/casing_program.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "io/number_parsing.h"
#include "io/section_table.h"
#include "io/text.h"
#include "io/units.h"

namespace caliper3d::io {

namespace {

constexpr double kMmPerInch = 25.4;
constexpr double kKgPerMPerLbPerFt = 1.48816394;  // 0.45359237 kg / 0.3048 m

// API Specification 5CT (ISO 11960), the casing list (table C.1; E.1 in USC units): label
// (outside diameter, in), nominal linear mass threaded and coupled (lb/ft), wall thickness (in).
struct ApiCasing {
    double od_in, weight_lbPerFt, wall_in;
};
constexpr ApiCasing kApi5ct[] = {
    {4.5, 9.50, 0.205},     {4.5, 10.50, 0.224},    {4.5, 11.60, 0.250},    {4.5, 13.50, 0.290},
    {4.5, 15.10, 0.337},    {5.0, 11.50, 0.220},    {5.0, 13.00, 0.253},    {5.0, 15.00, 0.296},
    {5.0, 18.00, 0.362},    {5.0, 21.40, 0.437},    {5.5, 14.00, 0.244},    {5.5, 15.50, 0.275},
    {5.5, 17.00, 0.304},    {5.5, 20.00, 0.361},    {5.5, 23.00, 0.415},    {6.625, 20.00, 0.288},
    {6.625, 24.00, 0.352},  {6.625, 28.00, 0.417},  {6.625, 32.00, 0.475},  {7.0, 17.00, 0.231},
    {7.0, 20.00, 0.272},    {7.0, 23.00, 0.317},    {7.0, 26.00, 0.362},    {7.0, 29.00, 0.408},
    {7.0, 32.00, 0.453},    {7.0, 35.00, 0.498},    {7.0, 38.00, 0.540},    {7.625, 24.00, 0.300},
    {7.625, 26.40, 0.328},  {7.625, 29.70, 0.375},  {7.625, 33.70, 0.430},  {7.625, 39.00, 0.500},
    {8.625, 24.00, 0.264},  {8.625, 28.00, 0.304},  {8.625, 32.00, 0.352},  {8.625, 36.00, 0.400},
    {8.625, 40.00, 0.450},  {8.625, 44.00, 0.500},  {8.625, 49.00, 0.557},  {9.625, 32.30, 0.312},
    {9.625, 36.00, 0.352},  {9.625, 40.00, 0.395},  {9.625, 43.50, 0.435},  {9.625, 47.00, 0.472},
    {9.625, 53.50, 0.545},  {10.75, 32.75, 0.279},  {10.75, 40.50, 0.350},  {10.75, 45.50, 0.400},
    {10.75, 51.00, 0.450},  {10.75, 55.50, 0.495},  {13.375, 48.00, 0.330}, {13.375, 54.50, 0.380},
    {13.375, 61.00, 0.430}, {13.375, 68.00, 0.480}, {13.375, 72.00, 0.514}, {16.0, 65.00, 0.375},
    {16.0, 75.00, 0.438},   {16.0, 84.00, 0.495},   {20.0, 94.00, 0.438},   {20.0, 106.50, 0.500},
    {20.0, 133.00, 0.635},
};

std::string fixed(double v, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

const LasItem* item(const LasHeader& h, const char* mnemonic) {
    const LasItem* i = h.parameter(mnemonic);
    if (!i || i->value.empty()) i = h.wellItem(mnemonic);
    return i && !i->value.empty() ? i : nullptr;
}

// A positive number of an item, NaN when it is absent, null or not positive (a 0 weight or
// shoe depth says "not known"); a value that is not a number is warned about.
double positiveValue(const LasHeader& h, const LasItem& i, const std::string& file,
                     Diagnostics* diagnostics) {
    double v = 0.0;
    if (!parseNumber(i.value, v) || !std::isfinite(v)) {
        if (diagnostics)
            diagnostics->warn(file, i.line,
                              i.mnemonic + " '" + i.value + "' is not a number; not read");
        return kNaN;
    }
    if ((h.hasNull && v == h.null) || !(v > 0.0)) return kNaN;
    return v;
}

// A length item converted by `scale(unit)`; NaN with a warning when its unit is not a length.
double length(const LasHeader& h, const LasItem& i, double toUnit_mm, const std::string& file,
              Diagnostics* diagnostics) {
    const double v = positiveValue(h, i, file, diagnostics);
    if (!std::isfinite(v)) return kNaN;
    const auto u = parseLengthUnit(i.unit);
    if (!u) {
        if (diagnostics)
            diagnostics->warn(file, i.line,
                              i.mnemonic + " " + i.value + " has no length unit (" +
                                  (i.unit.empty() ? "none" : "'" + i.unit + "'") + "); not read");
        return kNaN;
    }
    return v * toMillimetres(*u) / toUnit_mm;
}

// A linear mass unit: the factor to kg/m; NaN when unknown.
double massPerLength(std::string unit) {
    unit = upper(unit);
    unit.erase(std::remove(unit.begin(), unit.end(), ' '), unit.end());
    if (unit == "KG/M") return 1.0;
    for (const char* lb : {"LB/FT", "LB/F", "LBS/FT", "LBM/FT", "LBF/FT", "PPF", "#/FT"})
        if (unit == lb) return kKgPerMPerLbPerFt;
    return kNaN;
}

// Text split at commas, each part trimmed.
std::vector<std::string> parts(std::string_view text) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        std::string_view p =
            text.substr(start, comma == std::string_view::npos ? comma : comma - start);
        while (!p.empty() && std::isspace(static_cast<unsigned char>(p.front())))
            p.remove_prefix(1);
        while (!p.empty() && std::isspace(static_cast<unsigned char>(p.back()))) p.remove_suffix(1);
        out.emplace_back(p);
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    return out;
}

// "7in", "177.8mm", "17.78cm", "7" (inches): millimetres, NaN unless positive. `unitGiven`
// says whether a unit was written.
double lengthText_mm(std::string text, bool* unitGiven = nullptr) {
    double scale = kMmPerInch;
    if (unitGiven) *unitGiven = false;
    for (const char* suffix : {"mm", "in", "cm"}) {
        const std::string s(suffix);
        if (text.size() > s.size() && text.compare(text.size() - s.size(), s.size(), s) == 0) {
            scale = toMillimetres(*parseLengthUnit(s));
            text.resize(text.size() - s.size());
            if (unitGiven) *unitGiven = true;
            break;
        }
    }
    double v = 0.0;
    if (!parseNumber(text, v) || !std::isfinite(v) || !(v > 0.0)) return kNaN;
    return v * scale;
}

}  // namespace

double nominalCasingId_mm(double size_mm, double weight_kgPerM) {
    if (!std::isfinite(size_mm) || !std::isfinite(weight_kgPerM)) return kNaN;
    const double weight_lbPerFt = weight_kgPerM / kKgPerMPerLbPerFt;
    for (const ApiCasing& c : kApi5ct)
        if (std::abs(c.od_in * kMmPerInch - size_mm) <= 0.5 &&
            std::abs(c.weight_lbPerFt - weight_lbPerFt) <= 0.015 * c.weight_lbPerFt)
            return (c.od_in - 2.0 * c.wall_in) * kMmPerInch;
    return kNaN;
}

namespace {

// The header's current casing (the plain mnemonics); empty when it gives no shoe.
std::vector<CasingString> readCurrentCasing(const LasHeader& h, const std::string& file,
                                            Diagnostics* diagnostics) {
    CasingString c;
    std::string bottomFrom, driller;
    for (const char* m : {"CSGL", "CBLO", "CSGD", "CBDR"}) {
        const LasItem* i = item(h, m);
        if (!i) continue;
        const double bottom = length(h, *i, 1000.0, file, diagnostics);
        if (!std::isfinite(bottom)) continue;
        if (!std::isfinite(c.bottom_m)) {
            c.bottom_m = bottom;
            bottomFrom = m;
        } else if (driller.empty() && std::abs(bottom - c.bottom_m) > 0.005) {
            driller = std::string(m) + " " + fixed(bottom, 2) + " m";
        }
    }
    const LasItem* sizeItem = nullptr;
    for (const char* m : {"CSGS", "CSIZ"}) {
        if (const LasItem* i = item(h, m)) {
            c.size_mm = length(h, *i, 1.0, file, diagnostics);
            if (std::isfinite(c.size_mm)) {
                sizeItem = i;
                break;
            }
        }
    }
    if (!std::isfinite(c.bottom_m)) {
        if (sizeItem && diagnostics)
            diagnostics->warn(file, sizeItem->line,
                              sizeItem->mnemonic +
                                  " gives a casing size but no casing bottom depth (CSGL, CBLO, "
                                  "CSGD, CBDR) is given: no cased interval is marked");
        return {};
    }
    c.source = "~Parameter " + bottomFrom;
    if (!driller.empty()) c.source += " (" + driller + ")";
    if (sizeItem) c.source += ", " + sizeItem->mnemonic;
    if (const LasItem* i = item(h, "CSGW")) {
        const double w = positiveValue(h, *i, file, diagnostics);
        const double factor = massPerLength(i->unit);
        if (std::isfinite(w) && !std::isfinite(factor) && diagnostics)
            diagnostics->warn(file, i->line,
                              "CSGW " + i->value + " has no linear mass unit (kg/m, lb/ft; " +
                                  (i->unit.empty() ? "none" : "'" + i->unit + "'") + "); not read");
        c.weight_kgPerM = w * factor;
        if (std::isfinite(c.weight_kgPerM)) c.source += ", CSGW";
    }
    if (const LasItem* i = item(h, "CSGT")) c.type = i->value;
    c.innerDiameter_mm = nominalCasingId_mm(c.size_mm, c.weight_kgPerM);
    return {c};
}

// "FROM, TO" of a CSRG[n] item in metres; false with a warning when it is not two numbers of a
// length unit.
bool readInterval(const LasItem& i, double& from_m, double& to_m, const std::string& file,
                  Diagnostics* diagnostics) {
    const std::vector<std::string> p = parts(i.value);
    const auto unit = parseLengthUnit(i.unit);
    double a = 0.0, b = 0.0;
    if (p.size() != 2 || !unit || !parseNumber(p[0], a) || !parseNumber(p[1], b) || !(a <= b)) {
        if (diagnostics)
            diagnostics->warn(file, i.line,
                              i.mnemonic + " '" + i.value +
                                  "' is not two depths FROM, TO with a length unit; the casing "
                                  "is taken to hold over the whole log");
        return false;
    }
    // One factor (exactly 1 for metres), so that a depth written in metres reads back as the
    // very row depth it was written from.
    const double toMetres = toMillimetres(*unit) / 1000.0;
    from_m = a * toMetres;
    to_m = b * toMetres;
    return true;
}

// The numbered strings CSGL[n] ..., from n = 1 to the first without a shoe.
void readNumberedCasing(const LasHeader& h, const std::string& file, Diagnostics* diagnostics,
                        std::vector<CasingString>& out) {
    for (int n = 1;; ++n) {
        const std::string k = "[" + std::to_string(n) + "]";
        const LasItem* shoe = item(h, ("CSGL" + k).c_str());
        const double bottom = shoe ? length(h, *shoe, 1000.0, file, diagnostics) : kNaN;
        if (!std::isfinite(bottom)) return;
        CasingString c;
        c.bottom_m = bottom;
        c.source = "~Parameter CSGL" + k;
        if (const LasItem* i = item(h, ("CSGS" + k).c_str())) {
            c.size_mm = length(h, *i, 1.0, file, diagnostics);
            if (std::isfinite(c.size_mm)) c.source += ", CSGS" + k;
        }
        if (const LasItem* i = item(h, ("CSGW" + k).c_str())) {
            c.weight_kgPerM = positiveValue(h, *i, file, diagnostics) * massPerLength(i->unit);
            if (std::isfinite(c.weight_kgPerM)) c.source += ", CSGW" + k;
        }
        if (const LasItem* i = item(h, ("CSID" + k).c_str())) {
            c.innerDiameter_mm = length(h, *i, 1.0, file, diagnostics);
            if (std::isfinite(c.innerDiameter_mm)) c.source += ", CSID" + k;
        }
        if (!std::isfinite(c.innerDiameter_mm))
            c.innerDiameter_mm = nominalCasingId_mm(c.size_mm, c.weight_kgPerM);
        if (const LasItem* i = item(h, ("CSGT" + k).c_str())) c.type = i->value;
        if (const LasItem* i = item(h, ("CSRG" + k).c_str()))
            if (readInterval(*i, c.appliesFrom_m, c.appliesTo_m, file, diagnostics))
                c.source += ", CSRG" + k;
        out.push_back(c);
    }
}

// The shortest text that reads back to the same double, whatever the locale.
std::string exact(double v) {
    char buffer[32];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, v).ptr);
}

}  // namespace

std::vector<CasingString> readCasingProgram(const LasHeader& h, const std::string& file,
                                            Diagnostics* diagnostics) {
    std::vector<CasingString> out = readCurrentCasing(h, file, diagnostics);
    readNumberedCasing(h, file, diagnostics, out);
    return out;
}

std::vector<LasParameter> casingParameters(const std::vector<CasingString>& program) {
    std::vector<LasParameter> out;
    for (std::size_t n = 0; n < program.size(); ++n) {
        const CasingString& c = program[n];
        if (!std::isfinite(c.bottom_m)) continue;
        const std::string k = "[" + std::to_string(n + 1) + "]";
        const std::string of = ", string " + std::to_string(n + 1);
        out.push_back({"CSGL" + k, "M", exact(c.bottom_m), "casing shoe depth" + of});
        if (std::isfinite(c.size_mm))
            out.push_back({"CSGS" + k, "MM", exact(c.size_mm), "casing outer diameter" + of});
        if (std::isfinite(c.weight_kgPerM))
            out.push_back({"CSGW" + k, "KG/M", exact(c.weight_kgPerM), "casing weight" + of});
        if (std::isfinite(c.innerDiameter_mm))
            out.push_back(
                {"CSID" + k, "MM", exact(c.innerDiameter_mm), "casing inner diameter" + of});
        if (!c.type.empty()) out.push_back({"CSGT" + k, "", c.type, "casing type" + of});
        if (std::isfinite(c.appliesFrom_m) && std::isfinite(c.appliesTo_m))
            out.push_back({"CSRG" + k, "M", exact(c.appliesFrom_m) + ", " + exact(c.appliesTo_m),
                           "log depths this casing holds over" + of});
    }
    return out;
}

std::optional<CasingString> parseCasingSpec(std::string_view text, std::string& error) {
    const std::vector<std::string> p = parts(text);
    error =
        "expected BOTTOM,SIZE[,WEIGHT|ID]: the casing shoe's depth in metres, its outer "
        "diameter (7in, 177.8mm), then its weight (17lb/ft, 25.3kg/m) or inner diameter "
        "(6.538in, 166.1mm); found '" +
        std::string(text) + "'";
    if (p.size() < 2 || p.size() > 3) return std::nullopt;
    CasingString c;
    double bottom = 0.0;
    if (!parseNumber(p[0], bottom) || !std::isfinite(bottom) || !(bottom > 0.0))
        return std::nullopt;
    c.bottom_m = bottom;
    c.size_mm = lengthText_mm(p[1]);
    if (!std::isfinite(c.size_mm)) return std::nullopt;
    c.source = "--casing";
    if (p.size() == 3) {
        const std::string lower = [&] {
            std::string s = p[2];
            for (char& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
            return s;
        }();
        for (const char* unit : {"kg/m", "lb/ft"}) {
            const std::string u(unit);
            if (lower.size() > u.size() &&
                lower.compare(lower.size() - u.size(), u.size(), u) == 0) {
                double w = 0.0;
                if (!parseNumber(lower.substr(0, lower.size() - u.size()), w) ||
                    !std::isfinite(w) || !(w > 0.0))
                    return std::nullopt;
                c.weight_kgPerM = w * massPerLength(u);
            }
        }
        if (std::isfinite(c.weight_kgPerM)) {
            c.innerDiameter_mm = nominalCasingId_mm(c.size_mm, c.weight_kgPerM);
        } else {
            bool unitGiven = false;
            c.innerDiameter_mm = lengthText_mm(lower, &unitGiven);
            if (!unitGiven || !std::isfinite(c.innerDiameter_mm)) return std::nullopt;
            if (!(c.innerDiameter_mm < c.size_mm)) {
                error = "the inner diameter must be less than the outer diameter; found '" +
                        std::string(text) + "'";
                return std::nullopt;
            }
        }
    }
    error.clear();
    return c;
}

std::string casingSpecText(const CasingString& c) {
    std::string out = exact(c.bottom_m) + "," + exact(c.size_mm) + "mm";
    if (std::isfinite(c.weight_kgPerM))
        out += "," + exact(c.weight_kgPerM) + "kg/m";
    else if (std::isfinite(c.innerDiameter_mm))
        out += "," + exact(c.innerDiameter_mm) + "mm";
    return out;
}

std::string describeCasing(const CasingString& c) {
    std::string out;
    if (!c.type.empty()) out += c.type + " ";
    out += std::isfinite(c.size_mm)
               ? fixed(c.size_mm, 1) + " mm (" + fixed(c.size_mm / kMmPerInch, 3) + " in)"
               : std::string("casing of unknown size");
    if (std::isfinite(c.weight_kgPerM))
        out += ", " + fixed(c.weight_kgPerM, 1) + " kg/m (" +
               fixed(c.weight_kgPerM / kKgPerMPerLbPerFt, 2) + " lb/ft)";
    out += ", shoe at " + fixed(c.bottom_m, 2) + " m; ";
    if (std::isfinite(c.innerDiameter_mm))
        out += "nominal ID " + fixed(c.innerDiameter_mm, 2) + " mm" +
               (std::isfinite(c.weight_kgPerM) ? " (API 5CT)" : " (given)");
    else if (!std::isfinite(c.size_mm))
        out += "inner diameter unknown (no size)";
    else if (!std::isfinite(c.weight_kgPerM))
        out += "inner diameter unknown (no weight)";
    else
        out += "inner diameter unknown (size and weight not in the API 5CT table)";
    if (std::isfinite(c.appliesFrom_m) || std::isfinite(c.appliesTo_m))
        out +=
            "; holds over " +
            (std::isfinite(c.appliesFrom_m) ? fixed(c.appliesFrom_m, 2) : std::string("top")) +
            "-" +
            (std::isfinite(c.appliesTo_m) ? fixed(c.appliesTo_m, 2) + " m" : std::string("end")) +
            " of the log";
    if (!c.source.empty()) out += " [" + c.source + "]";
    return out;
}

const CasingString* casingAt(const std::vector<CasingString>& program, double md_m) {
    const CasingString* inside = nullptr;
    for (const CasingString& c : program) {
        if (!(md_m <= c.bottom_m) || md_m < c.appliesFrom_m || md_m > c.appliesTo_m) continue;
        if (!inside || (std::isfinite(c.size_mm) &&
                        (!std::isfinite(inside->size_mm) || c.size_mm < inside->size_mm)))
            inside = &c;
    }
    return inside;
}

}  // namespace caliper3d::io

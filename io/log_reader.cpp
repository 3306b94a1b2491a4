#include "io/log_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <numeric>
#include <sstream>

#include "io/column_text_reader.h"
#include "io/number_parsing.h"
#include "io/parse_error.h"

namespace caliper3d::io {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMaxPlausibleRadius_in = 30.0;

std::string upper(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return out;
}

// UTF-16 with a byte-order mark, as some Windows tools write LAS: decoded to
// UTF-8 (header text may hold a degree sign); unpaired surrogates are refused.
std::string fromUtf16IfMarked(std::string text, const std::string& name) {
    if (text.size() < 2) return text;
    const auto b0 = static_cast<unsigned char>(text[0]), b1 = static_cast<unsigned char>(text[1]);
    const bool le = b0 == 0xFF && b1 == 0xFE, be = b0 == 0xFE && b1 == 0xFF;
    if (!le && !be) return text;
    auto unit = [&](std::size_t i) {
        const unsigned lo = static_cast<unsigned char>(text[le ? i : i + 1]);
        const unsigned hi = static_cast<unsigned char>(text[le ? i + 1 : i]);
        return hi << 8 | lo;
    };
    std::string out;
    out.reserve(text.size() / 2);
    std::size_t line = 1;
    for (std::size_t i = 2; i + 1 < text.size(); i += 2) {
        unsigned c = unit(i);
        if (c >= 0xD800 && c <= 0xDBFF && i + 3 < text.size() && unit(i + 2) >= 0xDC00 && unit(i + 2) <= 0xDFFF) {
            c = 0x10000 + ((c - 0xD800) << 10) + (unit(i + 2) - 0xDC00);
            i += 2;
        } else if (c >= 0xD800 && c <= 0xDFFF) {
            throw ParseError(name, line, 0, "expected UTF-16 text, found an unpaired surrogate");
        }
        if (c == '\n') ++line;
        if (c < 0x80) {
            out.push_back(static_cast<char>(c));
        } else if (c < 0x800) {
            out.push_back(static_cast<char>(0xC0 | (c >> 6)));
            out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
        } else if (c < 0x10000) {
            out.push_back(static_cast<char>(0xE0 | (c >> 12)));
            out.push_back(static_cast<char>(0x80 | ((c >> 6) & 0x3F)));
            out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
        } else {
            out.push_back(static_cast<char>(0xF0 | (c >> 18)));
            out.push_back(static_cast<char>(0x80 | ((c >> 12) & 0x3F)));
            out.push_back(static_cast<char>(0x80 | ((c >> 6) & 0x3F)));
            out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
        }
    }
    return out;
}

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ParseError(path, 0, 0, "cannot open file for reading");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

bool looksLikeLas(const std::string& text) {
    std::size_t i = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
    while (i < text.size()) {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        if (i < text.size() && text[i] == '#') {
            i = text.find('\n', i);
            if (i == std::string::npos) return false;
            continue;
        }
        return i < text.size() && text[i] == '~';
    }
    return false;
}

// Factor to degrees for an angle unit; NaN when the unit is not an angle.
double angleScale(const std::string& unit) {
    const std::string u = upper(unit);
    if (u.empty() || u == "DEG" || u == "DEGA" || u == "DEGREES" || u == "DEGREE" || u == "\xC2\xB0") return 1.0;
    if (u == "RAD" || u == "RADIANS") return 180.0 / kPi;
    return std::nan("");
}

double medianStep(const std::vector<double>& depth) {
    if (depth.size() < 2) return 0.0;
    std::vector<double> steps(depth.size() - 1);
    for (std::size_t i = 1; i < depth.size(); ++i) steps[i - 1] = depth[i] - depth[i - 1];
    std::nth_element(steps.begin(), steps.begin() + static_cast<long>(steps.size() / 2), steps.end());
    return steps[steps.size() / 2];
}

// Applies a row permutation to every per-row vector of the table.
void permute(SectionTable& t, const std::vector<std::size_t>& order) {
    auto apply = [&](std::vector<double>& v, std::size_t width) {
        if (v.empty()) return;
        std::vector<double> out;
        out.reserve(order.size() * width);
        for (std::size_t r : order) out.insert(out.end(), v.begin() + static_cast<long>(r * width),
                                               v.begin() + static_cast<long>((r + 1) * width));
        v.swap(out);
    };
    apply(t.depth_m, 1);
    apply(t.radius_mm, static_cast<std::size_t>(t.armCount));
    apply(t.p1az_deg, 1);
    apply(t.devi_deg, 1);
    apply(t.hazi_deg, 1);
    apply(t.rb_deg, 1);
    apply(t.bitSize_mm, 1);
    for (ExtraCurve& c : t.extraCurves) apply(c.values, 1);
}

// Rows with a null depth are dropped; a log recorded upwards is sorted to
// increasing depth; a repeated depth keeps its first row. Each is a counted warning.
void orderByDepth(SectionTable& t, const std::string& file, Diagnostics& diagnostics) {
    const std::size_t n = t.rowCount();
    std::vector<std::size_t> keep;
    keep.reserve(n);
    std::size_t nullDepths = 0;
    for (std::size_t r = 0; r < n; ++r) {
        if (std::isfinite(t.depth_m[r])) keep.push_back(r);
        else ++nullDepths;
    }
    if (nullDepths) diagnostics.warn(file, 0, std::to_string(nullDepths) + " rows without a depth skipped");
    std::size_t descending = 0, ascending = 0;
    for (std::size_t i = 1; i < keep.size(); ++i) {
        const double a = t.depth_m[keep[i - 1]], b = t.depth_m[keep[i]];
        if (b < a) ++descending;
        if (b > a) ++ascending;
    }
    if (descending > 0) {
        std::stable_sort(keep.begin(), keep.end(),
                         [&](std::size_t a, std::size_t b) { return t.depth_m[a] < t.depth_m[b]; });
        diagnostics.warn(file, 0, ascending == 0 ? "log recorded upwards; rows sorted by increasing depth"
                                                 : std::to_string(descending) +
                                                       " rows out of depth order; rows sorted by increasing depth");
    }
    std::vector<std::size_t> order;
    order.reserve(keep.size());
    std::size_t repeated = 0;
    for (std::size_t r : keep) {
        if (!order.empty() && t.depth_m[r] == t.depth_m[order.back()]) {
            ++repeated;
            continue;
        }
        order.push_back(r);
    }
    if (repeated) diagnostics.warn(file, 0, std::to_string(repeated) + " rows repeat the depth of the row before; skipped");
    if (order.size() != n || descending > 0) permute(t, order);
}

void finishInfo(LoadedLog& loaded) {
    const SectionTable& t = loaded.table;
    LogInfo& info = loaded.info;
    info.rows = t.rowCount();
    info.arms = t.armCount;
    if (!t.depth_m.empty()) {
        info.top_m = t.depth_m.front();
        info.bottom_m = t.depth_m.back();
        info.step_m = medianStep(t.depth_m);
    }
    if (!t.bitSize_mm.empty()) info.bitSize_mm = t.bitSize_mm.front();
}

LoadedLog columnTextLog(const std::string& text, const std::string& name, const ReadOptions& options) {
    LoadedLog loaded;
    ColumnTextOptions c;
    c.armCount = options.armCount;
    c.depthUnit = options.depthUnit.value_or(LengthUnit::Metre);
    c.radiusUnit = options.radiusUnit.value_or(LengthUnit::Inch);
    c.rowStep_m = options.rowStep_m;
    loaded.table = parseColumnText(text, name, c, &loaded.info.diagnostics);
    if (!options.radiusUnit && c.radiusUnit == LengthUnit::Inch) {
        // Column text carries no units. Radii over kMaxPlausibleRadius_in inches
        // (a 1.5 m wide hole) are far likelier millimetres: read them so, and say so.
        std::vector<double> r = loaded.table.radius_mm;
        if (!r.empty()) {
            std::nth_element(r.begin(), r.begin() + static_cast<long>(r.size() / 2), r.end());
            const double median_in = r[r.size() / 2] / 25.4;
            if (median_in > kMaxPlausibleRadius_in) {
                for (double& v : loaded.table.radius_mm) v /= 25.4;
                c.radiusUnit = LengthUnit::Millimetre;
                loaded.info.diagnostics.warn(name, 0, "median radius " + std::to_string(median_in) +
                                                          " would be inches, far too large: read as millimetres "
                                                          "(give --radius-unit to choose)");
            }
        }
    }
    loaded.info.file = name;
    loaded.info.depthUnit = std::string(unitName(c.depthUnit));
    const int arms = loaded.table.armCount;
    if (loaded.table.p1az_deg.empty()) {
        loaded.info.format = "column text (" + std::to_string(arms) + " radii per line, no depth)";
        loaded.info.armSource = "radii columns 1.." + std::to_string(arms) + " (" + std::string(unitName(c.radiusUnit)) + ")";
    } else {
        loaded.info.format = "column text (depth R1..R" + std::to_string(arms) + " P1AZ DEVI HAZI)";
        loaded.info.armSource = "radii R1..R" + std::to_string(arms) + " (" + std::string(unitName(c.radiusUnit)) + ")";
    }
    loaded.info.curves.push_back({"depth", std::string(unitName(c.depthUnit)), "depth", 0});
    for (int k = 1; k <= arms; ++k)
        loaded.info.curves.push_back({"R" + std::to_string(k), std::string(unitName(c.radiusUnit)), "radius", 0});
    if (!loaded.table.p1az_deg.empty()) {
        loaded.info.curves.push_back({"P1AZ", "deg", "pad-1 azimuth", 0});
        loaded.info.curves.push_back({"DEVI", "deg", "deviation", 0});
        loaded.info.curves.push_back({"HAZI", "deg", "hole azimuth", 0});
    }
    if (options.bitSize_mm) loaded.table.bitSize_mm.assign(loaded.table.rowCount(), *options.bitSize_mm);
    orderByDepth(loaded.table, name, loaded.info.diagnostics);
    finishInfo(loaded);
    return loaded;
}

}  // namespace

LoadedLog sectionsFromLas(const LasLog& las, const ReadOptions& options, Diagnostics& diagnostics) {
    const LasHeader& h = las.header;
    const std::string& file = h.file;
    LoadedLog loaded;
    LogInfo& info = loaded.info;
    info.file = file;
    {
        std::ostringstream version;
        version << "LAS " << h.version << (h.version == std::floor(h.version) ? ".0" : "")
                << (h.wrap ? ", wrapped" : "");
        info.format = version.str();
    }
    if (const LasItem* well = h.wellItem("WELL")) info.wellName = well->value;

    std::vector<std::string> names;
    for (const LasCurve& c : las.curves) names.push_back(c.mnemonic);
    CurveRoles roles;
    try {
        roles = assignRoles(names, options.roles);
    } catch (const std::invalid_argument& e) {
        throw ParseError(file, 0, 0, e.what());
    }
    auto curveLine = [&](int curve) { return h.curves[static_cast<std::size_t>(curve)].line; };

    const std::size_t rows = las.rowCount();
    if (rows == 0) throw ParseError(file, h.dataFirstLine, 0, "expected data rows after ~A, found none");
    const bool caliper = !roles.radii.empty() || !roles.diameters.empty();
    SectionTable& t = loaded.table;
    t.source = file;
    const LasCurve& depth = las.curves[static_cast<std::size_t>(roles.depth)];
    std::string depthUnitText = depth.unit;
    if (depthUnitText.empty())
        if (const LasItem* strt = h.wellItem("STRT")) depthUnitText = strt->unit;
    info.depthUnit = depthUnitText;
    std::optional<LengthUnit> depthUnit = options.depthUnit ? options.depthUnit : parseLengthUnit(depthUnitText);
    if (!depthUnit) {
        if (!depthUnitText.empty())
            throw ParseError(file, curveLine(roles.depth), 0,
                             "expected a depth unit M or FT for " + depth.mnemonic + ", found '" + depthUnitText +
                                 "' (or give --depth-unit)");
        diagnostics.warn(file, curveLine(roles.depth), "depth has no unit; read as metres (give --depth-unit to change)");
        depthUnit = LengthUnit::Metre;
    }
    const double depthScale = toMetres(*depthUnit);
    t.depth_m.resize(rows);
    for (std::size_t r = 0; r < rows; ++r) t.depth_m[r] = depth.values[r] * depthScale;

    // Other depth curves (FMI files carry DEPT and DEPTH) are compared with the index.
    for (std::size_t c = 0; c < las.curves.size(); ++c) {
        if (static_cast<int>(c) == roles.depth || guessRole(las.curves[c].mnemonic).role != CurveRole::Depth) continue;
        std::size_t differ = 0;
        for (std::size_t r = 0; r < rows; ++r)
            if (std::abs(las.curves[c].values[r] - depth.values[r]) > 1e-6 * std::max(1.0, std::abs(depth.values[r]))) ++differ;
        if (differ)
            diagnostics.warn(file, h.curves[c].line, "depth curve " + las.curves[c].mnemonic + " differs from the index " +
                                                         depth.mnemonic + " on " + std::to_string(differ) +
                                                         " rows; the index is used");
    }

    auto lengthScale = [&](int curve) {
        const LasCurve& c = las.curves[static_cast<std::size_t>(curve)];
        if (options.radiusUnit) return toMillimetres(*options.radiusUnit);
        if (auto u = parseLengthUnit(c.unit)) return toMillimetres(*u);
        throw ParseError(file, curveLine(curve), 0,
                         "expected a length unit IN, MM or CM for caliper curve " + c.mnemonic + ", found '" + c.unit +
                             "' (or give --radius-unit)");
    };

    std::vector<int> armCurves;  // per arm: curve index, and the factor to a radius in mm
    std::vector<double> armScale;
    if (!caliper) {
        info.armSource = "none: no caliper curves found (name them with --radii or --diameters)";
    } else if (!roles.radii.empty()) {
        for (int c : roles.radii) {
            armCurves.push_back(c);
            armScale.push_back(lengthScale(c));
        }
        info.armSource = "radii";
        for (int c : roles.radii) info.armSource += " " + las.curves[static_cast<std::size_t>(c)].mnemonic;
    } else {
        // Opposite-pad diameters: pad k and pad k + n/2 share diameter C((k-1) mod n/2 + 1);
        // each is taken as two equal radii, so an off-centre tool is not visible.
        const int pairs = static_cast<int>(roles.diameters.size());
        for (int k = 0; k < 2 * pairs; ++k) {
            const int c = roles.diameters[static_cast<std::size_t>(k % pairs)];
            armCurves.push_back(c);
            armScale.push_back(lengthScale(c) / 2.0);
        }
        info.armSource = "diameters";
        for (int c : roles.diameters) info.armSource += " " + las.curves[static_cast<std::size_t>(c)].mnemonic;
        info.armSource += " (pad pairs; the tool is taken as centred)";
        diagnostics.warn(file, curveLine(roles.diameters.front()),
                         "radii from opposite-pad diameters: each pad pair is taken as centred on the tool");
    }
    t.armCount = static_cast<int>(armCurves.size());
    if (caliper && t.armCount < 3)
        throw ParseError(file, 0, 0, "expected at least 3 arm radii, found " + std::to_string(t.armCount));
    t.radius_mm.resize(rows * static_cast<std::size_t>(t.armCount));
    for (std::size_t r = 0; r < rows; ++r)
        for (int k = 0; k < t.armCount; ++k)
            t.radius_mm[r * static_cast<std::size_t>(t.armCount) + static_cast<std::size_t>(k)] =
                las.curves[static_cast<std::size_t>(armCurves[static_cast<std::size_t>(k)])].values[r] *
                armScale[static_cast<std::size_t>(k)];

    auto angles = [&](int curve, std::vector<double>& out) {
        if (curve < 0) return;
        const LasCurve& c = las.curves[static_cast<std::size_t>(curve)];
        const double scale = angleScale(c.unit);
        if (!std::isfinite(scale))
            throw ParseError(file, curveLine(curve), 0,
                             "expected an angle unit DEG or RAD for " + c.mnemonic + ", found '" + c.unit + "'");
        out.resize(rows);
        for (std::size_t r = 0; r < rows; ++r) out[r] = c.values[r] * scale;
    };
    angles(roles.padAzimuth, t.p1az_deg);
    angles(roles.deviation, t.devi_deg);
    angles(roles.holeAzimuth, t.hazi_deg);
    angles(roles.relativeBearing, t.rb_deg);

    if (options.bitSize_mm) {
        t.bitSize_mm.assign(rows, *options.bitSize_mm);
    } else if (roles.bitSize >= 0) {
        const double scale = lengthScale(roles.bitSize);
        t.bitSize_mm.resize(rows);
        for (std::size_t r = 0; r < rows; ++r)
            t.bitSize_mm[r] = las.curves[static_cast<std::size_t>(roles.bitSize)].values[r] * scale;
    } else {
        for (const char* name : {"BS", "BIT", "BITSIZE", "BIT_SIZE"}) {
            const LasItem* bs = h.parameter(name);
            if (!bs) bs = h.wellItem(name);
            double v = 0.0;
            if (!bs || !parseNumber(bs->value, v)) continue;
            const auto unit = parseLengthUnit(bs->unit);
            if (!unit) {
                diagnostics.warn(file, bs->line, "bit size " + bs->value + " has no length unit; ignored");
                break;
            }
            t.bitSize_mm.assign(rows, v * toMillimetres(*unit));
            break;
        }
    }

    for (std::size_t c = 0; c < las.curves.size(); ++c) {
        const LasCurve& curve = las.curves[c];
        const CurveRole role = roles.roleOf(static_cast<int>(c));
        info.curves.push_back({curve.mnemonic, curve.unit,
                               curve.text ? "text (skipped)" : std::string(roleName(role)), curve.nulls});
        if (role == CurveRole::Other && !curve.text && guessRole(curve.mnemonic).role != CurveRole::Depth)
            t.extraCurves.push_back({curve.mnemonic, curve.unit, curve.description, curve.values});
    }
    return loaded;
}

LoadedLog loadCaliperText(std::string text, const std::string& name, const ReadOptions& options) {
    text = fromUtf16IfMarked(std::move(text), name);
    if (!looksLikeLas(text)) return columnTextLog(text, name, options);
    Diagnostics diagnostics;
    LasReadOptions lasOptions;
    lasOptions.nullPolicy = options.nullPolicy;
    const LasLog las = readLas(text, name, lasOptions, &diagnostics);
    LoadedLog loaded = sectionsFromLas(las, options, diagnostics);
    orderByDepth(loaded.table, name, diagnostics);
    loaded.info.diagnostics = std::move(diagnostics);
    finishInfo(loaded);
    return loaded;
}

LoadedLog loadCaliperLog(const std::string& path, const ReadOptions& options) {
    return loadCaliperText(readFile(path), path, options);
}

SectionTable readCaliperLog(const std::string& path, const ReadOptions& options, Diagnostics* diagnostics) {
    LoadedLog loaded = loadCaliperLog(path, options);
    if (loaded.table.armCount == 0)
        throw ParseError(path, 0, 0,
                         "expected caliper curves (radii R1..Rn, RAD1..n, fingers F01..Fnn, or diameters C1, C2), "
                         "found none among " + std::to_string(loaded.info.curves.size()) +
                             " curves; name them with --radii or --diameters");
    if (diagnostics) {
        for (const Warning& w : loaded.info.diagnostics.warnings) diagnostics->warn(w.file, w.line, w.message);
        diagnostics->warningCount += loaded.info.diagnostics.warningCount - loaded.info.diagnostics.warnings.size();
    }
    return std::move(loaded.table);
}

std::string formatLogInfo(const LogInfo& info) {
    std::ostringstream out;
    out << "file:      " << info.file << "\n";
    out << "format:    " << info.format << "\n";
    if (!info.wellName.empty()) out << "well:      " << info.wellName << "\n";
    out << "rows:      " << info.rows << " sections\n";
    out.setf(std::ios::fixed);
    out.precision(4);
    out << "depth:     " << info.top_m << " to " << info.bottom_m << " m, step " << info.step_m << " m";
    if (!info.depthUnit.empty()) out << " (file unit " << info.depthUnit << ")";
    out << "\n";
    out << "arms:      " << info.arms << " from " << info.armSource << "\n";
    out.precision(1);
    if (std::isfinite(info.bitSize_mm)) out << "bit size:  " << info.bitSize_mm << " mm\n";
    else out << "bit size:  unknown (give --bit-size)\n";
    out << "curves:\n";
    for (const CurveInfo& c : info.curves) {
        out << "  " << c.mnemonic;
        for (std::size_t i = c.mnemonic.size(); i < 12; ++i) out << ' ';
        out << " " << (c.unit.empty() ? "-" : c.unit);
        for (std::size_t i = c.unit.empty() ? 1 : c.unit.size(); i < 8; ++i) out << ' ';
        out << " " << c.role;
        if (c.nulls) out << ", " << c.nulls << " nulls";
        out << "\n";
    }
    out << "warnings:  " << info.diagnostics.warningCount << "\n";
    for (const Warning& w : info.diagnostics.warnings) {
        out << "  " << w.file;
        if (w.line) out << ":" << w.line;
        out << ": " << w.message << "\n";
    }
    if (info.diagnostics.warningCount > info.diagnostics.warnings.size())
        out << "  (" << info.diagnostics.warningCount - info.diagnostics.warnings.size() << " more)\n";
    return out.str();
}

}  // namespace caliper3d::io

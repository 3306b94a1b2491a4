#include "io/curve_plan.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "io/number_parsing.h"
#include "io/parse_error.h"
#include "io/text.h"

namespace caliper3d::io {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

double angleScaleOf(const std::string& unit) {
    const std::string u = upper(unit);
    if (u.empty() || u == "DEG" || u == "DEGA" || u == "DEGREES" || u == "DEGREE" ||
        u == "\xC2\xB0")
        return 1.0;
    if (u == "RAD" || u == "RADIANS") return 180.0 / kPi;
    return std::nan("");
}

SectionTable CurvePlan::emptyTable(const std::vector<ColumnSpec>& columns) const {
    SectionTable t;
    t.armCount = armCount;
    for (int c : extraColumns) {
        const ColumnSpec& spec = columns[static_cast<std::size_t>(c)];
        t.extraCurves.push_back({spec.mnemonic, spec.unit, spec.description, {}});
    }
    return t;
}

void CurvePlan::mapRow(const double* raw, SectionTable& out) const {
    out.depth_m.push_back(raw[depthColumn] * depthScale);
    for (int k = 0; k < armCount; ++k)
        out.radius_mm.push_back(raw[armColumn[static_cast<std::size_t>(k)]] *
                                armScale[static_cast<std::size_t>(k)]);
    std::vector<double>* angles[4] = {&out.p1az_deg, &out.devi_deg, &out.hazi_deg, &out.rb_deg};
    for (int a = 0; a < 4; ++a) {
        if (angleColumn[a] < 0) continue;
        double v = raw[angleColumn[a]] * angleScale[a];
        if ((a == 0 || a == 3) && arm1FromPad1_deg != 0.0 && std::isfinite(v))
            v = std::fmod(v + arm1FromPad1_deg, 360.0);
        angles[a]->push_back(v);
    }
    if (bitSizeColumn >= 0)
        out.bitSize_mm.push_back(raw[bitSizeColumn] * bitSizeScale);
    else if (!std::isnan(bitSizeConstant))
        out.bitSize_mm.push_back(bitSizeConstant);
    for (std::size_t e = 0; e < extraColumns.size(); ++e)
        out.extraCurves[e].values.push_back(raw[extraColumns[e]]);
}

void CurvePlan::checkAngles(const double* raw, const std::string& file, std::size_t line) const {
    // P1AZ, DEVI, HAZI (RB is left alone, see the header).
    static constexpr double kMax[3] = {360.0, 180.0, 360.0};
    static constexpr const char* kWhat[3] = {"a pad azimuth", "an inclination", "a hole azimuth"};
    for (int a = 0; a < 3; ++a) {
        if (angleColumn[a] < 0) continue;
        const double v = raw[angleColumn[a]] * angleScale[a];
        if (std::isnan(v) || (v >= 0.0 && v <= kMax[a])) continue;
        char value[64];
        std::snprintf(value, sizeof value, "%g", v);
        throw ParseError(file, line, 0,
                         "expected " + std::string(kWhat[a]) + " from 0 to " +
                             std::to_string(static_cast<int>(kMax[a])) + " degrees in " +
                             angleName[a] + ", found " + value);
    }
}

namespace {

// makeCurvePlan's steps, one per part of the plan, sharing the columns, roles and messages.
class PlanBuilder {
public:
    PlanBuilder(const std::vector<ColumnSpec>& columns, const LasHeader* header,
                const ReadOptions& options, const std::string& file, LogInfo& info,
                Diagnostics& diagnostics)
        : m_columns(columns),
          m_header(header),
          m_options(options),
          m_file(file),
          m_info(info),
          m_diagnostics(diagnostics) {
        std::vector<std::string> names;
        names.reserve(columns.size());
        for (const ColumnSpec& c : columns) names.push_back(c.mnemonic);
        try {
            m_roles = assignRoles(names, options.roles);
        } catch (const std::invalid_argument& e) {
            throw ParseError(file, 0, 0, e.what());
        }
    }

    CurvePlan build() {
        depth();
        arms();
        angles();
        bitSize();
        curves();
        return std::move(m_plan);
    }

private:
    const ColumnSpec& spec(int c) const { return m_columns[static_cast<std::size_t>(c)]; }

    // Depth, in its own unit or STRT's; second depth curves to check against it.
    void depth() {
        m_plan.depthColumn = m_roles.depth;
        const ColumnSpec& depth = spec(m_roles.depth);
        std::string depthUnitText = depth.unit;
        if (depthUnitText.empty() && m_header)
            if (const LasItem* strt = m_header->wellItem("STRT")) depthUnitText = strt->unit;
        m_info.depthUnit = depthUnitText;
        std::optional<LengthUnit> depthUnit =
            m_options.depthUnit ? m_options.depthUnit : parseLengthUnit(depthUnitText);
        if (!depthUnit) {
            if (!depthUnitText.empty())
                throw ParseError(m_file, depth.line, 0,
                                 "expected a depth unit M or FT for " + depth.mnemonic +
                                     ", found '" + depthUnitText + "' (or give --depth-unit)");
            m_diagnostics.warn(m_file, depth.line,
                               "depth has no unit; read as metres (give --depth-unit to change)");
            depthUnit = LengthUnit::Metre;
        }
        m_plan.depthScale = toMetres(*depthUnit);
        for (std::size_t c = 0; c < m_columns.size(); ++c)
            if (static_cast<int>(c) != m_roles.depth &&
                guessRole(m_columns[c].mnemonic).role == CurveRole::Depth && !m_columns[c].text)
                m_plan.otherDepthColumns.push_back(static_cast<int>(c));
    }

    double lengthScale(int c) const {
        if (m_options.radiusUnit) return toMillimetres(*m_options.radiusUnit);
        if (auto u = parseLengthUnit(spec(c).unit)) return toMillimetres(*u);
        throw ParseError(m_file, spec(c).line, 0,
                         "expected a length unit IN, MM or CM for caliper curve " +
                             spec(c).mnemonic + ", found '" + spec(c).unit +
                             "' (or give --radius-unit)");
    }

    void arms() {
        if (!m_roles.radii.empty()) {
            m_info.armSource = "radii";
            for (int c : m_roles.radii) {
                m_plan.armColumn.push_back(c);
                m_plan.armScale.push_back(lengthScale(c));
                m_info.armSource += " " + spec(c).mnemonic;
            }
        } else if (!m_roles.diameters.empty()) {
            diameters();
        } else {
            m_info.armSource =
                "none: no caliper curves found (name them with --radii or --diameters)";
            m_diagnostics.warn(m_file, 0,
                               "no caliper curve recognised: name the arm radii with --radii or "
                               "the pad-pair diameters with --diameters (the curves and their "
                               "descriptions are listed by caliper3d info)");
        }
        m_plan.armCount = static_cast<int>(m_plan.armColumn.size());
        if (m_plan.armCount == 1)
            throw ParseError(m_file, spec(m_plan.armColumn.front()).line, 0,
                             "expected at least 2 arm radii (or one diameter), found 1: " +
                                 spec(m_plan.armColumn.front()).mnemonic);
        if (m_plan.armCount == 2)
            m_diagnostics.warn(
                m_file, spec(m_plan.armColumn.front()).line,
                "two pads measure one diameter: each section is drawn as the circle through both");
    }

    // Opposite-pad diameters: pad k and pad k + n/2 share diameter C((k-1) mod n/2 + 1)
    // (C1 = pads 1-3, C2 = pads 2-4 on four-arm tools); each is taken as two equal radii.
    void diameters() {
        const int pairs = static_cast<int>(m_roles.diameters.size());
        for (int k = 0; k < 2 * pairs; ++k) {
            const int c = m_roles.diameters[static_cast<std::size_t>(k % pairs)];
            m_plan.armColumn.push_back(c);
            m_plan.armScale.push_back(lengthScale(c) / 2.0);
        }
        m_info.armSource = "diameters";
        for (int c : m_roles.diameters) m_info.armSource += " " + spec(c).mnemonic;
        if (m_roles.toolPads > 2 * pairs && m_roles.armsAligned) {
            char offset[96];
            std::snprintf(offset, sizeof offset,
                          " (pad pairs of a tool with %d pads, arm 1 %.0f deg", m_roles.toolPads,
                          m_roles.arm1FromPad1_deg);
            m_info.armSource += offset;
            m_info.armSource += " clockwise of pad 1; the tool is taken as centred)";
            m_plan.arm1FromPad1_deg = m_roles.arm1FromPad1_deg;
        } else if (!m_roles.armsAligned) {
            m_info.armSource += " (X-Y calipers; the tool is taken as centred)";
        } else {
            m_info.armSource += " (pad pairs; the tool is taken as centred)";
        }
        m_diagnostics.warn(
            m_file, spec(m_roles.diameters.front()).line,
            "radii from opposite-pad diameters: each pad pair is taken as centred on the tool");
    }

    void angles() {
        const int angleRoles[4] = {m_roles.padAzimuth, m_roles.deviation, m_roles.holeAzimuth,
                                   m_roles.relativeBearing};
        for (int a = 0; a < 4; ++a) {
            const int c = angleRoles[a];
            if (c < 0) continue;
            if ((a == 0 || a == 3) && !m_roles.armsAligned && !m_roles.diameters.empty()) {
                // X-Y calipers: where pad 1 points says nothing of where they point.
                m_unplacedAngles.push_back(c);
                m_diagnostics.warn(m_file, spec(c).line,
                                   spec(c).mnemonic +
                                       " not used: the calipers' bearing from pad 1 is not "
                                       "known, so the sections have no orientation (azimuths "
                                       "unknown)");
                continue;
            }
            const double scale = angleScaleOf(spec(c).unit);
            if (!std::isfinite(scale))
                throw ParseError(m_file, spec(c).line, 0,
                                 "expected an angle unit DEG or RAD for " + spec(c).mnemonic +
                                     ", found '" + spec(c).unit + "'");
            m_plan.angleColumn[a] = c;
            m_plan.angleScale[a] = scale;
            m_plan.angleName[a] = spec(c).mnemonic;
        }
    }

    // An override, a BS curve, or a BS parameter of the header.
    void bitSize() {
        if (m_options.bitSize_mm) {
            m_plan.bitSizeConstant = *m_options.bitSize_mm;
        } else if (m_roles.bitSize >= 0) {
            m_plan.bitSizeColumn = m_roles.bitSize;
            m_plan.bitSizeScale = lengthScale(m_roles.bitSize);
        } else if (m_header) {
            for (const char* name : {"BS", "BIT", "BITSIZE", "BIT_SIZE"}) {
                const LasItem* bs = m_header->parameter(name);
                if (!bs) bs = m_header->wellItem(name);
                double v = 0.0;
                if (!bs || !parseNumber(bs->value, v)) continue;
                const auto unit = parseLengthUnit(bs->unit);
                if (!unit) {
                    m_diagnostics.warn(m_file, bs->line,
                                       "bit size " + bs->value + " has no length unit; ignored");
                    break;
                }
                m_plan.bitSizeConstant = v * toMillimetres(*unit);
                break;
            }
        }
        m_info.bitSize_mm = m_plan.bitSizeConstant;
    }

    // Every curve's role as info lists it; the other curves kept as extra curves.
    void curves() {
        for (std::size_t c = 0; c < m_columns.size(); ++c) {
            const ColumnSpec& col = m_columns[c];
            CurveRole role = m_roles.roleOf(static_cast<int>(c));
            if (role == CurveRole::Radius && guessRole(col.mnemonic).role == CurveRole::Finger)
                role = CurveRole::Finger;
            const bool secondDepth =
                std::find(m_plan.otherDepthColumns.begin(), m_plan.otherDepthColumns.end(),
                          static_cast<int>(c)) != m_plan.otherDepthColumns.end();
            const bool unplaced = std::find(m_unplacedAngles.begin(), m_unplacedAngles.end(),
                                            static_cast<int>(c)) != m_unplacedAngles.end();
            const bool unusedCaliper =
                std::find(m_roles.unusedCalipers.begin(), m_roles.unusedCalipers.end(),
                          static_cast<int>(c)) != m_roles.unusedCalipers.end();
            std::string roleText = col.text        ? "text (skipped)"
                                   : secondDepth   ? "second depth (checked against the index)"
                                   : unplaced      ? "orientation (not used: calipers not placed)"
                                   : unusedCaliper ? "caliper (not used for the arms)"
                                                   : std::string(roleName(role));
            m_info.curves.push_back(
                {col.mnemonic, col.unit, std::move(roleText), 0, col.description});
            if (role == CurveRole::Other && !col.text &&
                guessRole(col.mnemonic).role != CurveRole::Depth)
                m_plan.extraColumns.push_back(static_cast<int>(c));
        }
    }

    const std::vector<ColumnSpec>& m_columns;
    const LasHeader* m_header;
    const ReadOptions& m_options;
    const std::string& m_file;
    LogInfo& m_info;
    Diagnostics& m_diagnostics;
    CurveRoles m_roles;
    CurvePlan m_plan;
    std::vector<int> m_unplacedAngles;  // pad azimuth and RB left out: calipers not placed
};

}  // namespace

CurvePlan makeCurvePlan(const std::vector<ColumnSpec>& columns, const LasHeader* header,
                        const ReadOptions& options, const std::string& file, LogInfo& info,
                        Diagnostics& diagnostics) {
    return PlanBuilder(columns, header, options, file, info, diagnostics).build();
}

namespace {
std::string_view trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}
}  // namespace

std::pair<std::string_view, std::string_view> splitColumnName(std::string_view name) {
    for (auto [open, close] : {std::pair<char, char>{'(', ')'}, {'[', ']'}}) {
        const std::size_t o = name.find(open);
        if (o != std::string_view::npos && o > 0 && name.back() == close)
            return {name.substr(0, o), trimmed(name.substr(o + 1, name.size() - o - 2))};
    }
    const std::size_t u = name.rfind('_');
    if (u != std::string_view::npos && u > 0 && u + 1 < name.size()) {
        const std::string_view unit = name.substr(u + 1);
        if (parseLengthUnit(unit) || std::isfinite(angleScaleOf(std::string(unit))))
            return {name.substr(0, u), unit};
    }
    return {name, {}};
}

}  // namespace caliper3d::io

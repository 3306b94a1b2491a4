#include "io/curve_roles.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <stdexcept>

namespace caliper3d::io {

namespace {

std::string canonical(std::string_view mnemonic) {
    std::string s(mnemonic);
    const std::size_t copy = s.find(':');  // "SFLU:2", a duplicate renamed by the reader
    if (copy != std::string::npos) s.resize(copy);
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return s;
}

bool startsWith(const std::string& s, std::string_view prefix) {
    return s.rfind(prefix, 0) == 0;
}

// "RAD12QH" after prefix "RAD": 12; also "NAME[12]" (LAS 3.0 arrays). 0 when no number.
int numberAfter(const std::string& s, std::size_t at, bool allowSuffix) {
    std::size_t i = at;
    if (i < s.size() && s[i] == '[') ++i;
    const std::size_t digits = i;
    int n = 0;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])) && i - digits < 3)
        n = n * 10 + (s[i++] - '0');
    if (i == digits) return 0;
    if (i < s.size() && s[i] == ']') ++i;
    if (i == s.size()) return n;
    if (!allowSuffix) return 0;
    for (std::size_t k = i; k < s.size(); ++k)
        if (!std::isalpha(static_cast<unsigned char>(s[k]))) return 0;
    return n;
}

}  // namespace

std::string_view roleName(CurveRole role) {
    switch (role) {
        case CurveRole::Depth:
            return "depth";
        case CurveRole::Radius:
            return "radius";
        case CurveRole::Diameter:
            return "diameter";
        case CurveRole::Finger:
            return "finger radius";
        case CurveRole::PadAzimuth:
            return "pad-1 azimuth";
        case CurveRole::Deviation:
            return "deviation";
        case CurveRole::HoleAzimuth:
            return "hole azimuth";
        case CurveRole::RelativeBearing:
            return "relative bearing";
        case CurveRole::BitSize:
            return "bit size";
        case CurveRole::Other:
            return "other";
    }
    return "other";
}

const std::vector<MnemonicEntry>& mnemonicTable() {
    using R = CurveRole;
    static const std::vector<MnemonicEntry> table = {
        {"DEPT", false, {R::Depth}, "every LAS (the index)"},
        {"DEPTH", false, {R::Depth}, "LAS, column text"},
        {"MD", false, {R::Depth}, "column text, survey exports"},
        {"TDEP", false, {R::Depth}, "DLIS-converted logs (Schlumberger)"},
        // Pad-pair diameters: pair k joins pads k and k + pads/2.
        {"C1", false, {R::Diameter, 1}, "Schlumberger FMI, FMS, OBMI, HDT/SHDT dipmeters"},
        {"C2", false, {R::Diameter, 2}, "Schlumberger FMI, FMS, OBMI, HDT/SHDT dipmeters"},
        {"C3", false, {R::Diameter, 3}, "six-arm calipers"},
        {"C13", false, {R::Diameter, 1, 4}, "four-pad dipmeters (pads 1-3)"},
        {"C24", false, {R::Diameter, 2, 4}, "four-pad dipmeters (pads 2-4)"},
        // Two perpendicular calipers whose bearing from pad 1 the file does not give.
        {"IECX", false, {R::Diameter, 1, 4, false}, "Weatherford CMI (MIE caliper X)"},
        {"IECY", false, {R::Diameter, 2, 4, false}, "Weatherford CMI (MIE caliper Y)"},
        {"CALX", false, {R::Diameter, 1, 4, false}, "X-Y calipers"},
        {"CALY", false, {R::Diameter, 2, 4, false}, "X-Y calipers"},
        // The one diameter of two-arm tools: arm 0, used only when nothing else is a caliper.
        {"HCAL", false, {R::Diameter}, "Schlumberger HRLA/HNGS (high-resolution caliper)"},
        {"CALI", false, {R::Diameter}, "most vendors (caliper)"},
        {"CAL", false, {R::Diameter}, "most vendors (caliper)"},
        {"CALS", false, {R::Diameter}, "sonic caliper"},
        {"CAL1", false, {R::Diameter}, "numbered calipers of a tool string (first)"},
        {"CAL2", false, {R::Diameter}, "numbered calipers of a tool string (second)"},
        {"CAL3", false, {R::Diameter}, "numbered calipers of a tool string (third)"},
        {"CALD", false, {R::Diameter}, "density caliper"},
        {"CLDC", false, {R::Diameter}, "Halliburton density caliper"},
        {"CALN", false, {R::Diameter}, "neutron caliper"},
        {"LCAL", false, {R::Diameter}, "Schlumberger Platform Express caliper"},
        {"CALA", false, {R::Diameter}, "Baker Atlas caliper"},
        // Orientation.
        {"P1AZ", false, {R::PadAzimuth}, "Schlumberger FMI, FMS, OBMI, UBI"},
        {"P1AZ_", true, {R::PadAzimuth}, "Schlumberger, with a tool suffix (P1AZ_FBST)"},
        {"AZST", true, {R::PadAzimuth}, "Baker STAR imager (AZSTQH)"},
        {"IAP1", false, {R::PadAzimuth}, "Weatherford CMI (azimuth of reference, pad 1)"},
        {"RB", true, {R::RelativeBearing}, "Schlumberger (RB), Baker STAR (RBSTQH)"},
        {"IRBR", false, {R::RelativeBearing}, "Weatherford CMI"},
        {"DEVI", false, {R::Deviation}, "Schlumberger GPIT"},
        {"DEV", true, {R::Deviation}, "DEVIM, Baker DEVSTQH, DEVIATION"},
        {"INC", false, {R::Deviation}, "surveys, LWD"},
        {"INCL", false, {R::Deviation}, "surveys, LWD"},
        {"INCLIN", false, {R::Deviation}, "surveys"},
        {"INCLINATION", false, {R::Deviation}, "surveys, LAS 3.0"},
        {"ITLT", false, {R::Deviation}, "Weatherford CMI (borehole tilt)"},
        {"HAZ", true, {R::HoleAzimuth}, "Schlumberger HAZI, HAZIM"},
        {"AZI", false, {R::HoleAzimuth}, "surveys"},
        {"AZIM", false, {R::HoleAzimuth}, "surveys"},
        {"AZIMUTH", false, {R::HoleAzimuth}, "surveys, LAS 3.0"},
        {"DAZ", false, {R::HoleAzimuth}, "Schlumberger (deviation azimuth)"},
        {"HLAZ", false, {R::HoleAzimuth}, "Schlumberger dipmeters (hole azimuth)"},
        {"IAZT", false, {R::HoleAzimuth}, "Weatherford CMI (borehole azimuth)"},
        {"BS", false, {R::BitSize}, "most vendors"},
        {"BIT", false, {R::BitSize}, "most vendors"},
        {"BITSIZE", false, {R::BitSize}, "column text"},
    };
    return table;
}

RoleGuess guessRole(std::string_view mnemonic) {
    const std::string m = canonical(mnemonic);
    // Numbered families first: radii, fingers and the DIab pad-pair diameters.
    if (startsWith(m, "RADIUS")) {
        if (int n = numberAfter(m, 6, true)) return {CurveRole::Radius, n};
    }
    if (startsWith(m, "RAD")) {
        if (int n = numberAfter(m, 3, true)) return {CurveRole::Radius, n};
    }
    if (startsWith(m, "R") && !startsWith(m, "RB")) {
        if (int n = numberAfter(m, 1, false)) return {CurveRole::Radius, n};
    }
    if (startsWith(m, "FING")) {
        if (int n = numberAfter(m, m.size() > 6 && m.compare(0, 6, "FINGER") == 0 ? 6 : 4, false))
            return {CurveRole::Finger, n};
    }
    if (startsWith(m, "F")) {
        if (int n = numberAfter(m, 1, false)) return {CurveRole::Finger, n};
    }
    // Elements of an array channel named for its radii or fingers as a whole (DLIS and LAS
    // 3.0 arrays: "RADI[7]", "FINGERS[40]").
    const std::size_t bracket = m.find('[');
    if (bracket != std::string::npos && bracket > 0) {
        const std::string base = m.substr(0, bracket);
        const int n = numberAfter(m, bracket, false);
        if (n && (base == "RADI" || base == "RADII" || base == "RADS" || base == "RADIUS"))
            return {CurveRole::Radius, n};
        if (n && (base == "FINGERS" || base == "FINGER")) return {CurveRole::Finger, n};
    }
    // DIab: the diameter between pads a and b of a tool with 2 (b - a) pads (Weatherford
    // CMI: DI15, DI26, DI37, DI48, "Imager Diameter 2 - 6").
    if (m.size() == 4 && m[0] == 'D' && m[1] == 'I' && m[2] >= '1' && m[2] <= '9' && m[3] > m[2] &&
        m[3] <= '9')
        return {CurveRole::Diameter, m[2] - '0', 2 * (m[3] - m[2])};
    for (const MnemonicEntry& e : mnemonicTable())
        if (e.prefix ? startsWith(m, e.name) : m == e.name) return e.guess;
    return {CurveRole::Other, 0};
}

CurveRole CurveRoles::roleOf(int curve) const {
    if (curve == depth) return CurveRole::Depth;
    if (std::find(radii.begin(), radii.end(), curve) != radii.end()) return CurveRole::Radius;
    if (std::find(diameters.begin(), diameters.end(), curve) != diameters.end())
        return CurveRole::Diameter;
    if (curve == padAzimuth) return CurveRole::PadAzimuth;
    if (curve == deviation) return CurveRole::Deviation;
    if (curve == holeAzimuth) return CurveRole::HoleAzimuth;
    if (curve == relativeBearing) return CurveRole::RelativeBearing;
    if (curve == bitSize) return CurveRole::BitSize;
    return CurveRole::Other;
}

namespace {
int indexOf(const std::vector<std::string>& mnemonics, const std::string& wanted) {
    const std::string w = canonical(wanted);
    for (std::size_t i = 0; i < mnemonics.size(); ++i)
        if (canonical(mnemonics[i]) == w && mnemonics[i].find(':') == std::string::npos)
            return static_cast<int>(i);
    throw std::invalid_argument("no curve named '" + wanted + "' in the log");
}

// One named curve, or for "NAME[]" every element NAME[1], NAME[2], ... of a
// LAS 3.0 array channel, in index order (a 40-finger array in one word).
std::vector<int> indicesOf(const std::vector<std::string>& mnemonics, const std::string& wanted) {
    if (wanted.size() < 3 || wanted.compare(wanted.size() - 2, 2, "[]") != 0)
        return {indexOf(mnemonics, wanted)};
    const std::string array = canonical(wanted.substr(0, wanted.size() - 2)) + "[";
    std::vector<int> out;
    for (int element = 1;; ++element) {
        const std::string name = array + std::to_string(element) + "]";
        auto it = std::find_if(mnemonics.begin(), mnemonics.end(), [&](const std::string& m) {
            return m.find(':') == std::string::npos && canonical(m) == name;
        });
        if (it == mnemonics.end()) break;
        out.push_back(static_cast<int>(it - mnemonics.begin()));
    }
    if (out.empty())
        throw std::invalid_argument("no array '" + wanted + "' (elements " + array +
                                    "1], ...) in the log");
    return out;
}

// Arm numbers 1..n without gaps, first curve per arm.
std::vector<int> armSequence(const std::map<int, int>& byArm) {
    std::vector<int> out;
    for (int arm = 1; byArm.count(arm); ++arm) out.push_back(byArm.at(arm));
    return out;
}

// A pad-pair diameter curve: its index, pair number and what its name says of the tool.
struct PairCurve {
    int index = -1;
    RoleGuess guess;
};

// The pad-pair diameters chosen from one family of names.
struct PairChoice {
    std::vector<int> curves;  // pair order
    int pads = 0;
    double arm1FromPad1_deg = 0.0;
    bool aligned = true;
};

// The most equally spaced pairs of one family: pairs p0, p0 + s, p0 + 2s, ... covering half
// the tool's pads evenly (for an eight-pad tool: 1-4 all, or 1 and 3, or 2 and 4), so that
// the arms they give are evenly spaced. Fewer than two pairs: none.
PairChoice choosePairs(const std::vector<PairCurve>& family) {
    PairChoice out;
    if (family.empty()) return out;
    out.aligned = family.front().guess.aligned;
    std::map<int, int> byPair;
    for (const PairCurve& c : family) byPair.emplace(c.guess.arm, c.index);
    const int pads = family.front().guess.pads;
    if (pads == 0) {  // C1, C2, C3: the tool has two pads per pair present
        out.curves = armSequence(byPair);
        out.pads = 2 * static_cast<int>(out.curves.size());
        if (out.curves.size() < 2) out.curves.clear();
        return out;
    }
    const int half = pads / 2;
    for (int step = 1; half / step >= 2; ++step) {
        if (half % step != 0) continue;
        for (int first = 1; first <= step; ++first) {
            std::vector<int> curves;
            for (int pair = first; pair <= half && byPair.count(pair); pair += step)
                curves.push_back(byPair.at(pair));
            if (static_cast<int>(curves.size()) != half / step) continue;
            out.curves = std::move(curves);
            out.pads = pads;
            out.arm1FromPad1_deg = 360.0 * (first - 1) / pads;
            return out;
        }
    }
    return out;
}

// The best family of pad-pair diameters: calipers of known bearing first, then the most pairs.
PairChoice bestPairs(const std::vector<PairCurve>& pairs) {
    std::map<std::pair<int, bool>, std::vector<PairCurve>> families;
    for (const PairCurve& c : pairs) families[{c.guess.pads, c.guess.aligned}].push_back(c);
    PairChoice best;
    for (const auto& [key, family] : families) {
        PairChoice c = choosePairs(family);
        if (c.curves.empty()) continue;
        const bool better = best.curves.empty() || (c.aligned && !best.aligned) ||
                            (c.aligned == best.aligned && c.curves.size() > best.curves.size());
        if (better) best = std::move(c);
    }
    return best;
}

// An orientation curve named on the command line: its index, -1 for "none".
void overrideAngle(const std::vector<std::string>& mnemonics, const std::string& name, int& slot) {
    if (name.empty()) return;
    slot = canonical(name) == "NONE" ? -1 : indexOf(mnemonics, name);
}

// Every curve's guess: the single roles set in `roles` (first curve of each), the arm curves
// gathered for the choice of arms.
struct ArmCandidates {
    std::map<int, int> radii, fingers;
    std::vector<PairCurve> pairs;
    std::vector<int> singles;  // one-diameter calipers, in file order
};

ArmCandidates collectRoles(const std::vector<std::string>& mnemonics, CurveRoles& roles) {
    ArmCandidates c;
    for (std::size_t i = 0; i < mnemonics.size(); ++i) {
        if (mnemonics[i].find(':') != std::string::npos) continue;  // a duplicate: never a role
        const int index = static_cast<int>(i);
        const RoleGuess g = guessRole(mnemonics[i]);
        auto first = [&](int& slot) {
            if (slot < 0) slot = index;
        };
        switch (g.role) {
            case CurveRole::Depth:
                first(roles.depth);
                break;
            case CurveRole::Radius:
                c.radii.emplace(g.arm, index);
                break;
            case CurveRole::Finger:
                c.fingers.emplace(g.arm, index);
                break;
            case CurveRole::Diameter:
                if (g.arm > 0)
                    c.pairs.push_back({index, g});
                else
                    c.singles.push_back(index);
                break;
            case CurveRole::PadAzimuth:
                first(roles.padAzimuth);
                break;
            case CurveRole::Deviation:
                first(roles.deviation);
                break;
            case CurveRole::HoleAzimuth:
                first(roles.holeAzimuth);
                break;
            case CurveRole::RelativeBearing:
                first(roles.relativeBearing);
                break;
            case CurveRole::BitSize:
                first(roles.bitSize);
                break;
            case CurveRole::Other:
                break;
        }
    }
    return c;
}
}  // namespace

CurveRoles assignRoles(const std::vector<std::string>& mnemonics, const RoleOverrides& overrides) {
    CurveRoles roles;
    const ArmCandidates candidates = collectRoles(mnemonics, roles);
    const std::map<int, int>& radii = candidates.radii;
    const std::map<int, int>& fingers = candidates.fingers;
    const std::vector<PairCurve>& pairs = candidates.pairs;
    const std::vector<int>& singles = candidates.singles;
    if (roles.depth < 0 && !mnemonics.empty())
        roles.depth = 0;  // LAS: the first curve is the index
    overrideAngle(mnemonics, overrides.padAzimuth, roles.padAzimuth);
    overrideAngle(mnemonics, overrides.relativeBearing, roles.relativeBearing);
    overrideAngle(mnemonics, overrides.deviation, roles.deviation);
    overrideAngle(mnemonics, overrides.holeAzimuth, roles.holeAzimuth);

    auto takePairs = [&](const PairChoice& c) {
        roles.diameters = c.curves;
        roles.toolPads = c.pads;
        roles.arm1FromPad1_deg = c.arm1FromPad1_deg;
        roles.armsAligned = c.aligned;
    };
    if (!overrides.radii.empty()) {
        for (const std::string& name : overrides.radii)
            for (int index : indicesOf(mnemonics, name)) roles.radii.push_back(index);
    } else if (!overrides.diameters.empty()) {
        std::vector<PairCurve> named;
        for (const std::string& name : overrides.diameters)
            for (int index : indicesOf(mnemonics, name)) {
                roles.diameters.push_back(index);
                const RoleGuess g = guessRole(mnemonics[static_cast<std::size_t>(index)]);
                if (g.role == CurveRole::Diameter && g.arm > 0) named.push_back({index, g});
            }
        // Named pad pairs of one known tool keep their bearing from pad 1 (DI26, DI48).
        if (named.size() == roles.diameters.size()) {
            const PairChoice c = bestPairs(named);
            if (c.curves.size() == roles.diameters.size()) takePairs(c);
        }
    } else {
        // Most arms first: radii, fingers, opposite-pad diameters (C1, C2, ..., DI26, DI48);
        // then the two-pad tools: two radii, or one diameter (C1 alone, or CALI, HCAL, ...).
        roles.radii = armSequence(radii);
        if (roles.radii.size() < 3) roles.radii = armSequence(fingers);
        if (roles.radii.size() < 3) {
            roles.radii.clear();
            takePairs(bestPairs(pairs));
        }
        if (roles.radii.empty() && roles.diameters.empty()) {
            const std::vector<int> two = armSequence(radii);
            auto c1 = std::find_if(pairs.begin(), pairs.end(), [](const PairCurve& c) {
                return c.guess.arm == 1 && c.guess.pads == 0;
            });
            if (two.size() == 2) {
                roles.radii = two;
            } else if (c1 != pairs.end()) {
                roles.diameters = {c1->index};
            } else if (!singles.empty()) {
                roles.diameters = {singles.front()};
            }
        }
    }
    for (const PairCurve& c : pairs)
        if (roles.roleOf(c.index) == CurveRole::Other) roles.unusedCalipers.push_back(c.index);
    for (int c : singles)
        if (roles.roleOf(c) == CurveRole::Other) roles.unusedCalipers.push_back(c);
    std::sort(roles.unusedCalipers.begin(), roles.unusedCalipers.end());
    return roles;
}

}  // namespace caliper3d::io

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

RoleGuess guessRole(std::string_view mnemonic) {
    const std::string m = canonical(mnemonic);
    if (m == "DEPT" || m == "DEPTH" || m == "MD" || m == "TDEP") return {CurveRole::Depth, 0};
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
    if (m.size() == 2 && m[0] == 'C' && m[1] >= '1' && m[1] <= '3')
        return {CurveRole::Diameter, m[1] - '0'};
    // The single caliper of two-arm tools (density, sonic): one diameter, arm 0.
    if (m == "CALI" || m == "CAL" || m == "HCAL" || m == "CALS") return {CurveRole::Diameter, 0};
    if (m == "P1AZ" || startsWith(m, "P1AZ_") || startsWith(m, "AZST"))
        return {CurveRole::PadAzimuth, 0};
    if (m == "DEVI" || m == "INC" || m == "INCL" || startsWith(m, "DEV"))
        return {CurveRole::Deviation, 0};
    if (m == "AZIM" || m == "AZI" || startsWith(m, "HAZ")) return {CurveRole::HoleAzimuth, 0};
    if (startsWith(m, "RB")) return {CurveRole::RelativeBearing, 0};
    if (m == "BS" || m == "BIT" || m == "BITSIZE") return {CurveRole::BitSize, 0};
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
}  // namespace

CurveRoles assignRoles(const std::vector<std::string>& mnemonics, const RoleOverrides& overrides) {
    CurveRoles roles;
    std::map<int, int> radii, fingers, diameters;
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
                radii.emplace(g.arm, index);
                break;
            case CurveRole::Finger:
                fingers.emplace(g.arm, index);
                break;
            case CurveRole::Diameter:
                diameters.emplace(g.arm, index);
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
    if (roles.depth < 0 && !mnemonics.empty())
        roles.depth = 0;  // LAS: the first curve is the index

    if (!overrides.radii.empty()) {
        for (const std::string& name : overrides.radii)
            for (int index : indicesOf(mnemonics, name)) roles.radii.push_back(index);
    } else if (!overrides.diameters.empty()) {
        for (const std::string& name : overrides.diameters)
            for (int index : indicesOf(mnemonics, name)) roles.diameters.push_back(index);
    } else {
        // Most arms first: radii, fingers, opposite-pad diameters (C1, C2, ...); then
        // the two-pad tools: two radii, or one diameter (C1 alone, or CALI, HCAL, ...).
        roles.radii = armSequence(radii);
        if (roles.radii.size() < 3) roles.radii = armSequence(fingers);
        if (roles.radii.size() < 3) {
            roles.radii.clear();
            roles.diameters = armSequence(diameters);
            if (roles.diameters.size() < 2) roles.diameters.clear();
        }
        if (roles.radii.empty() && roles.diameters.empty()) {
            const std::vector<int> two = armSequence(radii);
            if (two.size() == 2) {
                roles.radii = two;
            } else if (diameters.count(1)) {
                roles.diameters = {diameters.at(1)};
            } else if (diameters.count(0)) {
                roles.diameters = {diameters.at(0)};
            }
        }
    }
    return roles;
}

}  // namespace caliper3d::io

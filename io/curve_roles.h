#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace caliper3d::io {

// What a log curve means to caliper3d.
enum class CurveRole {
    Depth,            // DEPT, DEPTH, MD, TDEP
    Radius,           // R1..Rn, RAD1..n with vendor suffixes (RAD1QH), RADIUS1..n
    Diameter,         // C1, C2, C3: opposite-pad diameters of 4- and 6-arm tools
    Finger,           // F01..F60, FING01..: multi-finger radii
    PadAzimuth,       // P1AZ, P1AZ_*, AZST* (azimuth of pad 1)
    Deviation,        // DEVI, DEVIM, DEV*, INC, INCL
    HoleAzimuth,      // HAZI, HAZ*, AZIM, AZI
    RelativeBearing,  // RB, RB*
    BitSize,          // BS, BIT, BITSIZE
    Other             // kept for colouring
};
std::string_view roleName(CurveRole role);

// The role a mnemonic's name suggests, and for arm curves its 1-based arm
// number (0 otherwise). For a pad-pair diameter, `arm` is the pair (pads
// arm and arm + pads/2), `pads` the pads of the tool when the name says
// (DI26 of an eight-pad imager: pair 2 of 8; 0 when the tool has two pads
// per pair present), and `aligned` false for X/Y calipers whose bearing
// from pad 1 is not known.
struct RoleGuess {
    CurveRole role = CurveRole::Other;
    int arm = 0;
    int pads = 0;
    bool aligned = true;
};
RoleGuess guessRole(std::string_view mnemonic);

// One row of the table of fixed names (docs/formats.md, "Curve roles"): the
// name, or its prefix, the role, and the tools it comes from. The numbered
// families (R1.., RAD1.., F01.., DI15..) are matched by guessRole itself.
struct MnemonicEntry {
    const char* name;
    bool prefix;
    RoleGuess guess;
    const char* tool;
};
const std::vector<MnemonicEntry>& mnemonicTable();

// Explicit choices from the command line (--radii R1,R2,... --diameters C1,C2);
// an empty field means "detect". "NAME[]" names every element NAME[1],
// NAME[2], ... of a LAS 3.0 array channel, in index order.
// The orientation curves (--pad-azimuth, --relative-bearing, --inclination,
// --hole-azimuth) are one name each; "none" means the log has no such curve
// (a curve the user does not trust is left out).
struct RoleOverrides {
    std::vector<std::string> radii;
    std::vector<std::string> diameters;
    std::string padAzimuth;
    std::string relativeBearing;
    std::string deviation;
    std::string holeAzimuth;
};
inline bool operator==(const RoleOverrides& a, const RoleOverrides& b) {
    return a.radii == b.radii && a.diameters == b.diameters && a.padAzimuth == b.padAzimuth &&
           a.relativeBearing == b.relativeBearing && a.deviation == b.deviation &&
           a.holeAzimuth == b.holeAzimuth;
}
inline bool operator!=(const RoleOverrides& a, const RoleOverrides& b) {
    return !(a == b);
}

// Indices into a curve list, -1 when absent.
struct CurveRoles {
    int depth = -1;
    std::vector<int> radii;      // arm order (radii or fingers)
    std::vector<int> diameters;  // pad-pair order
    int padAzimuth = -1;
    int deviation = -1;
    int holeAzimuth = -1;
    int relativeBearing = -1;
    int bitSize = -1;
    // Pad-pair diameters: the pads of the tool (0 when not stated), and the
    // angle clockwise from pad 1 to arm 1 (45 degrees for pairs 2-6 and 4-8
    // of an eight-pad imager). `armsAligned` false: the calipers' bearing
    // from pad 1 is unknown (X/Y calipers), so the sections have no known
    // orientation whatever the log's pad azimuth says.
    int toolPads = 0;
    double arm1FromPad1_deg = 0.0;
    bool armsAligned = true;
    std::vector<int> unusedCalipers;  // caliper curves recognised but not used for the arms
    CurveRole roleOf(int curve) const;
};

// Picks one curve per role from `mnemonics` (the index is the first curve
// when none is named as depth). Arm curves must number 1..n without gaps;
// radii win over fingers, fingers over diameters. Throws std::invalid_argument
// when an override names a curve that is not there.
CurveRoles assignRoles(const std::vector<std::string>& mnemonics, const RoleOverrides& overrides);

}  // namespace caliper3d::io

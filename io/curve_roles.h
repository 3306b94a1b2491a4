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
// number (0 otherwise). The table is walked entry by entry in tests.
struct RoleGuess {
    CurveRole role = CurveRole::Other;
    int arm = 0;
};
RoleGuess guessRole(std::string_view mnemonic);

// Explicit choices from the command line (--radii R1,R2,... --diameters C1,C2);
// an empty field means "detect". "NAME[]" names every element NAME[1],
// NAME[2], ... of a LAS 3.0 array channel, in index order.
struct RoleOverrides {
    std::vector<std::string> radii;
    std::vector<std::string> diameters;
};
inline bool operator==(const RoleOverrides& a, const RoleOverrides& b) {
    return a.radii == b.radii && a.diameters == b.diameters;
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
    CurveRole roleOf(int curve) const;
};

// Picks one curve per role from `mnemonics` (the index is the first curve
// when none is named as depth). Arm curves must number 1..n without gaps;
// radii win over fingers, fingers over diameters. Throws std::invalid_argument
// when an override names a curve that is not there.
CurveRoles assignRoles(const std::vector<std::string>& mnemonics, const RoleOverrides& overrides);

}  // namespace caliper3d::io

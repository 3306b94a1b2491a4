#include "io/curve_roles.h"

#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

using namespace caliper3d::io;

namespace {
RoleOverrides radiiNamed(std::vector<std::string> names) {
    RoleOverrides o;
    o.radii = std::move(names);
    return o;
}
RoleOverrides diametersNamed(std::vector<std::string> names) {
    RoleOverrides o;
    o.diameters = std::move(names);
    return o;
}
}  // namespace

// Every entry of the mnemonic table, and near misses that must stay "other".
TEST(CurveRolesTest, EveryAliasInTheTableIsRecognised) {
    struct Case {
        const char* mnemonic;
        CurveRole role;
        int arm;
    };
    const Case cases[] = {
        {"DEPT", CurveRole::Depth, 0},
        {"DEPTH", CurveRole::Depth, 0},
        {"MD", CurveRole::Depth, 0},
        {"TDEP", CurveRole::Depth, 0},
        {"R1", CurveRole::Radius, 1},
        {"R12", CurveRole::Radius, 12},
        {"RAD1", CurveRole::Radius, 1},
        {"RAD6QH", CurveRole::Radius, 6},
        {"RADIUS3", CurveRole::Radius, 3},
        {"rad2qh", CurveRole::Radius, 2},
        {"F01", CurveRole::Finger, 1},
        {"F60", CurveRole::Finger, 60},
        {"FING07", CurveRole::Finger, 7},
        {"FINGER24", CurveRole::Finger, 24},
        {"FING[3]", CurveRole::Finger, 3},
        {"FINGERS[40]", CurveRole::Finger, 40},
        {"RADI[7]", CurveRole::Radius, 7},
        {"RADS[2]", CurveRole::Radius, 2},
        {"C1", CurveRole::Diameter, 1},
        {"C2", CurveRole::Diameter, 2},
        {"C3", CurveRole::Diameter, 3},
        {"P1AZ", CurveRole::PadAzimuth, 0},
        {"P1AZ_FBST", CurveRole::PadAzimuth, 0},
        {"AZSTQH", CurveRole::PadAzimuth, 0},
        {"DEVI", CurveRole::Deviation, 0},
        {"DEVIM", CurveRole::Deviation, 0},
        {"DEVSTQH", CurveRole::Deviation, 0},
        {"INC", CurveRole::Deviation, 0},
        {"INCL", CurveRole::Deviation, 0},
        {"HAZI", CurveRole::HoleAzimuth, 0},
        {"HAZIM", CurveRole::HoleAzimuth, 0},
        {"AZIM", CurveRole::HoleAzimuth, 0},
        {"AZI", CurveRole::HoleAzimuth, 0},
        {"RB", CurveRole::RelativeBearing, 0},
        {"RBSTQH", CurveRole::RelativeBearing, 0},
        {"BS", CurveRole::BitSize, 0},
        {"BIT", CurveRole::BitSize, 0},
        {"BITSIZE", CurveRole::BitSize, 0},
        // the one diameter of two-arm tools (arm 0: used only when nothing else is a caliper)
        {"CALI", CurveRole::Diameter, 0},
        {"HCAL", CurveRole::Diameter, 0},
        {"CAL1", CurveRole::Diameter, 0},
        {"CAL2", CurveRole::Diameter, 0},
        {"LCAL", CurveRole::Diameter, 0},
        // Weatherford CMI eight-pad imager
        {"DI15", CurveRole::Diameter, 1},
        {"DI26", CurveRole::Diameter, 2},
        {"DI37", CurveRole::Diameter, 3},
        {"DI48", CurveRole::Diameter, 4},
        {"IECX", CurveRole::Diameter, 1},
        {"IECY", CurveRole::Diameter, 2},
        {"IAP1", CurveRole::PadAzimuth, 0},
        {"IRBR", CurveRole::RelativeBearing, 0},
        {"ITLT", CurveRole::Deviation, 0},
        {"IAZT", CurveRole::HoleAzimuth, 0},
        // path curves under their long names
        {"INCLINATION", CurveRole::Deviation, 0},
        {"AZIMUTH", CurveRole::HoleAzimuth, 0},
        {"DAZ", CurveRole::HoleAzimuth, 0},
        {"HLAZ", CurveRole::HoleAzimuth, 0},
        // near misses
        {"RHOB", CurveRole::Other, 0},
        {"RX0", CurveRole::Other, 0},
        {"RAZGSTQH", CurveRole::Other, 0},
        {"FFI", CurveRole::Other, 0},
        {"FD", CurveRole::Other, 0},
        {"C4", CurveRole::Other, 0},
        {"CALIP", CurveRole::Other, 0},
        {"GR", CurveRole::Other, 0},
        {"DT", CurveRole::Other, 0},
        {"R1X", CurveRole::Other, 0},
        {"DIP1QH", CurveRole::Other, 0},
        {"P1NO_FBST", CurveRole::Other, 0},
        {"DCAL", CurveRole::Other, 0},  // caliper minus bit size: not a diameter
        {"DI62", CurveRole::Other, 0},
        {"DI1", CurveRole::Other, 0},
        {"AZ", CurveRole::Other, 0},
    };
    for (const Case& c : cases) {
        const RoleGuess g = guessRole(c.mnemonic);
        EXPECT_EQ(g.role, c.role) << c.mnemonic;
        EXPECT_EQ(g.arm, c.arm) << c.mnemonic;
    }
    for (CurveRole role :
         {CurveRole::Depth, CurveRole::Radius, CurveRole::Diameter, CurveRole::Finger,
          CurveRole::PadAzimuth, CurveRole::Deviation, CurveRole::HoleAzimuth,
          CurveRole::RelativeBearing, CurveRole::BitSize, CurveRole::Other})
        EXPECT_FALSE(roleName(role).empty());
}

// Every row of the table is matched by its own name (a prefix row by the name plus a suffix),
// to the role and arm the row gives.
TEST(CurveRolesTest, EveryRowOfTheTableMatchesItsName) {
    ASSERT_GT(mnemonicTable().size(), 40u);
    for (const MnemonicEntry& e : mnemonicTable()) {
        const std::string name = std::string(e.name) + (e.prefix ? "QH" : "");
        const RoleGuess g = guessRole(name);
        EXPECT_EQ(g.role, e.guess.role) << name;
        EXPECT_EQ(g.arm, e.guess.arm) << name;
        EXPECT_EQ(g.aligned, e.guess.aligned) << name;
        EXPECT_STRNE(e.tool, "") << name;
    }
}

// The CMI repeat pass logs pad pairs 2-6 and 4-8 of eight pads: four arms 90 degrees apart,
// arm 1 on pad 2, 45 degrees clockwise of pad 1 (where IAP1 points).
TEST(CurveRolesTest, EightPadImagerPairsTwoAndFourGiveFourArmsFromPadTwo) {
    const CurveRoles cmi = assignRoles({"DEPT", "GRGM", "IECX", "IECY", "IRBR", "ITLT", "IAP1",
                                        "IAZT", "DI26", "DI48", "BTM1", "BIT"},
                                       {});
    EXPECT_EQ(cmi.diameters, (std::vector<int>{8, 9}));
    EXPECT_EQ(cmi.toolPads, 8);
    EXPECT_DOUBLE_EQ(cmi.arm1FromPad1_deg, 45.0);
    EXPECT_TRUE(cmi.armsAligned);
    EXPECT_EQ(cmi.padAzimuth, 6);
    EXPECT_EQ(cmi.relativeBearing, 4);
    EXPECT_EQ(cmi.deviation, 5);
    EXPECT_EQ(cmi.holeAzimuth, 7);
    EXPECT_EQ(cmi.bitSize, 11);
    EXPECT_EQ(cmi.unusedCalipers, (std::vector<int>{2, 3}));  // IECX, IECY

    const CurveRoles all = assignRoles({"DEPT", "DI48", "DI15", "DI37", "DI26"}, {});
    EXPECT_EQ(all.diameters, (std::vector<int>{2, 4, 3, 1}));  // pairs 1, 2, 3, 4
    EXPECT_DOUBLE_EQ(all.arm1FromPad1_deg, 0.0);
    const CurveRoles odd = assignRoles({"DEPT", "DI15", "DI26", "DI48"}, {});
    EXPECT_EQ(odd.diameters, (std::vector<int>{2, 3}));  // 1, 2, 4 are not evenly spaced
    EXPECT_DOUBLE_EQ(odd.arm1FromPad1_deg, 45.0);

    // X-Y calipers alone: used, but their bearing from pad 1 is unknown.
    const CurveRoles xy = assignRoles({"DEPT", "IAP1", "IECX", "IECY"}, {});
    EXPECT_EQ(xy.diameters, (std::vector<int>{2, 3}));
    EXPECT_FALSE(xy.armsAligned);

    // Named by hand, DI26 and DI48 keep their bearing from pad 1.
    const CurveRoles named =
        assignRoles({"DEPT", "DI26", "DI48"}, diametersNamed({"DI26", "DI48"}));
    EXPECT_DOUBLE_EQ(named.arm1FromPad1_deg, 45.0);
}

TEST(CurveRolesTest, OrientationCurvesCanBeNamedOrLeftOut) {
    const std::vector<std::string> curves = {"DEPT", "R1",   "R2",   "R3",     "P1AZ",
                                             "RB",   "DEVI", "HAZI", "TOOLAZ", "ANG"};
    RoleOverrides o;
    o.padAzimuth = "TOOLAZ";
    o.relativeBearing = "none";
    o.deviation = "ang";
    o.holeAzimuth = "NONE";
    const CurveRoles r = assignRoles(curves, o);
    EXPECT_EQ(r.padAzimuth, 8);
    EXPECT_EQ(r.relativeBearing, -1);
    EXPECT_EQ(r.deviation, 9);
    EXPECT_EQ(r.holeAzimuth, -1);
    o.padAzimuth = "MISSING";
    EXPECT_THROW(assignRoles(curves, o), std::invalid_argument);
}

TEST(CurveRolesTest, ArmsMustNumberWithoutGapsAndRadiiWinOverDiameters) {
    const CurveRoles star = assignRoles({"DEPT", "AZSTQH", "DEVSTQH", "RAD1QH", "RAD2QH", "RAD3QH",
                                         "RAD4QH", "RAD5QH", "RAD6QH", "RBSTQH", "GR"},
                                        {});
    EXPECT_EQ(star.depth, 0);
    EXPECT_EQ(star.radii, (std::vector<int>{3, 4, 5, 6, 7, 8}));
    EXPECT_EQ(star.padAzimuth, 1);
    EXPECT_EQ(star.deviation, 2);
    EXPECT_EQ(star.relativeBearing, 9);
    EXPECT_EQ(star.holeAzimuth, -1);
    EXPECT_EQ(star.roleOf(10), CurveRole::Other);

    const CurveRoles gap = assignRoles({"DEPT", "R1", "R2", "R4", "C1", "C2"}, {});
    EXPECT_TRUE(gap.radii.empty());  // R3 missing: radii unusable, diameters used
    EXPECT_EQ(gap.diameters, (std::vector<int>{4, 5}));

    const CurveRoles fmi =
        assignRoles({"DEPT", "BS", "C1", "C2", "DEPTH", "DEVIM", "HAZI", "P1AZ", "RB"}, {});
    EXPECT_EQ(fmi.depth, 0);
    EXPECT_EQ(fmi.diameters, (std::vector<int>{2, 3}));
    EXPECT_EQ(fmi.bitSize, 1);

    // Single-diameter calipers: the first one found, when nothing else measures the hole.
    const CurveRoles welly = assignRoles({"DEPT", "GR", "CAL1", "CAL2", "RHOB"}, {});
    EXPECT_EQ(welly.diameters, (std::vector<int>{2}));
    EXPECT_EQ(welly.unusedCalipers, (std::vector<int>{3}));
}

TEST(CurveRolesTest, OverridesNameTheCurvesAndUnknownNamesAreRefused) {
    const CurveRoles r = assignRoles({"DEPT", "A", "B", "C", "GR"}, radiiNamed({"A", "B", "C"}));
    EXPECT_EQ(r.radii, (std::vector<int>{1, 2, 3}));
    EXPECT_THROW(assignRoles({"DEPT", "A"}, radiiNamed({"A", "Z", "Y"})), std::invalid_argument);
    EXPECT_EQ(assignRoles({"MD", "R1", "R2", "R3"}, {}).depth, 0);
    EXPECT_EQ(assignRoles({"TIME", "MD", "R1", "R2", "R3"}, {}).depth, 1);
}

TEST(CurveRolesTest, AnArrayOverrideNamesEveryElementInIndexOrder) {
    const CurveRoles r =
        assignRoles({"DEPT", "CAL[2]", "CAL[1]", "CAL[3]", "GR", "CAL[5]"}, radiiNamed({"CAL[]"}));
    EXPECT_EQ(r.radii, (std::vector<int>{
                           2, 1, 3}));  // CAL[5] is not after CAL[3]: the array stops at the gap
    EXPECT_THROW(assignRoles({"DEPT", "CAL[1]"}, radiiNamed({"MFC[]"})), std::invalid_argument);
}

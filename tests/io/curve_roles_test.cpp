#include "io/curve_roles.h"

#include <gtest/gtest.h>

using namespace caliper3d::io;

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
}

TEST(CurveRolesTest, OverridesNameTheCurvesAndUnknownNamesAreRefused) {
    const CurveRoles r = assignRoles({"DEPT", "A", "B", "C", "GR"}, {{"A", "B", "C"}, {}});
    EXPECT_EQ(r.radii, (std::vector<int>{1, 2, 3}));
    EXPECT_THROW(assignRoles({"DEPT", "A"}, {{"A", "Z", "Y"}, {}}), std::invalid_argument);
    EXPECT_EQ(assignRoles({"MD", "R1", "R2", "R3"}, {}).depth, 0);
    EXPECT_EQ(assignRoles({"TIME", "MD", "R1", "R2", "R3"}, {}).depth, 1);
}

TEST(CurveRolesTest, AnArrayOverrideNamesEveryElementInIndexOrder) {
    const CurveRoles r =
        assignRoles({"DEPT", "CAL[2]", "CAL[1]", "CAL[3]", "GR", "CAL[5]"}, {{"CAL[]"}, {}});
    EXPECT_EQ(r.radii, (std::vector<int>{
                           2, 1, 3}));  // CAL[5] is not after CAL[3]: the array stops at the gap
    EXPECT_THROW(assignRoles({"DEPT", "CAL[1]"}, {{"MFC[]"}, {}}), std::invalid_argument);
}

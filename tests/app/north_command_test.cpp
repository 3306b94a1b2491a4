// `caliper3d info` says which north every azimuth is from and which declination was
// applied (docs/conventions.md, "North"), with the options --declination,
// --grid-convergence and --azimuth-north.
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "cli_run.h"
#include "test_support.h"

using namespace caliper3d;
using caliper3d::test::CommandRun;
using caliper3d::test::runCaliper3d;

namespace {

// Six arms, P1AZ 100 and HAZI 50 degrees from magnetic north on every row.
std::string magneticLog() {
    const auto path = test::scratch("north_command_magnetic.las");
    std::ostringstream s;
    s << "~Version\nVERS. 2.0 :\nWRAP. NO :\n~Well\nSTRT.M 100.0 :\nSTOP.M 100.4 :\n"
      << "STEP.M 0.1 :\nNULL. -999.25 :\nWELL. NORTH : well\n~Curve\nDEPT.M : depth\n";
    for (int arm = 1; arm <= 6; ++arm) s << "R" << arm << ".MM : radius " << arm << "\n";
    s << "P1AZ.DEG : pad 1 azimuth (magnetic)\nDEVI.DEG : inclination\n"
      << "HAZI.DEG : hole azimuth relative to magnetic north\n"
      << "~Parameter\nMDEC.DEG 10.5 : magnetic declination\n~A\n";
    for (int row = 0; row < 5; ++row)
        s << 100.0 + 0.1 * row << " 108 108 108 108 108 108 100 2 50\n";
    std::ofstream(path) << s.str();
    return path.string();
}

}  // namespace

TEST(NorthCommandTest, InfoShowsTheHeadersDeclinationOrTheOptions) {
    const std::string log = magneticLog();
    const CommandRun header = runCaliper3d("info '" + log + "'");
    EXPECT_EQ(header.status, 0) << header.output;
    EXPECT_NE(header.output.find("\nnorth:     P1AZ (pad-1 azimuth) from magnetic north"),
              std::string::npos)
        << header.output;
    EXPECT_NE(header.output.find("declination 10.50 E from the header's MDEC (~Parameter, line"),
              std::string::npos)
        << header.output;
    const CommandRun option = runCaliper3d("info --declination -2.5 '" + log + "'");
    EXPECT_EQ(option.status, 0) << option.output;
    EXPECT_NE(option.output.find("declination 2.50 W from --declination applied"),
              std::string::npos)
        << option.output;
    const CommandRun bad = runCaliper3d("info --azimuth-north sideways '" + log + "'");
    EXPECT_EQ(bad.status, 2) << bad.output;
    EXPECT_NE(bad.output.find("--azimuth-north: expected 'true', 'magnetic' or 'grid'"),
              std::string::npos)
        << bad.output;
}

TEST(NorthCommandTest, InfoOnTheRealFmiLogSaysTrueNorthAndLeavesMdecUnapplied) {
    const auto file = test::sharedData() / "real" / "1AA063409108W400_FMI_SONIC_MAIN.las";
    CALIPER3D_REQUIRE_DATA(file);
    const CommandRun r = runCaliper3d("info '" + file.string() + "'");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("\nnorth:     P1AZ (pad-1 azimuth) from true north, its description "
                            "'PAD 1 AZIMUTH IN HORIZONTAL PLANE (0 = TRUE NORTH)'; HAZI (hole "
                            "azimuth) from true north"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("declination 14.38 E in MDEC (~Parameter, line 123) not applied"),
              std::string::npos)
        << r.output;
}

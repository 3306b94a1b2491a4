// An inclination outside [0, 180] degrees or a pad or hole azimuth outside
// [0, 360] is bad input naming file and line (docs/formats.md), in column
// text and LAS alike, on the streamed, threaded and wrapped paths.
#include <string>

#include <gtest/gtest.h>

#include "io/log_reader.h"
#include "io/parse_error.h"

using namespace caliper3d::io;

namespace {

// Column text in the reference layout: depth R1..R6 P1AZ DEVI HAZI.
std::string columnText(const std::string& p1az, const std::string& devi, const std::string& hazi) {
    return "10.0 4.25 4.25 4.25 4.25 4.25 4.25 10 1 20\n"
           "10.1 4.25 4.25 4.25 4.25 4.25 4.25 10 1 20\n"
           "10.2 4.25 4.25 4.25 4.25 4.25 4.25 " +
           p1az + " " + devi + " " + hazi +
           "\n"
           "10.3 4.25 4.25 4.25 4.25 4.25 4.25 10 1 20\n";
}

std::string las(const std::string& p1az, const std::string& devi, const std::string& hazi,
                bool wrapped = false) {
    std::string text = "~Version\n VERS. 2.0 :\n WRAP. " + std::string(wrapped ? "YES" : "NO") +
                       " :\n~Well\n NULL. -999.25 :\n~Curve\n DEPT.M :\n R1.IN :\n R2.IN :\n"
                       " R3.IN :\n R4.IN :\n P1AZ.DEG :\n DEVI.DEG :\n HAZI.DEG :\n~A\n";
    // Wrapped: the depth on a line of its own, then the other values.
    const std::string rows[] = {"10.0", "4 4 4 4 10 1 20",
                                "10.1", "4 4 4 4 " + p1az + " " + devi + " " + hazi,
                                "10.2", "4 4 4 4 10 1 20"};
    for (int i = 0; i < 6; ++i) text += rows[i] + (wrapped || i % 2 == 1 ? "\n" : " ");
    return text;  // unwrapped, the second data row is line 17
}

std::string refusal(const std::string& text, const std::string& name) {
    try {
        loadCaliperText(text, name, ReadOptions{});
    } catch (const ParseError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(AngleRangeTest, InclinationOver180InColumnTextIsBadInputNamingFileAndLine) {
    EXPECT_EQ(refusal(columnText("10", "181", "20"), "w.txt"),
              "w.txt:3: expected an inclination from 0 to 180 degrees in DEVI, found 181");
}

TEST(AngleRangeTest, AzimuthOver360OrNegativeInColumnTextIsBadInput) {
    EXPECT_EQ(refusal(columnText("10", "1", "361"), "w.txt"),
              "w.txt:3: expected a hole azimuth from 0 to 360 degrees in HAZI, found 361");
    EXPECT_EQ(refusal(columnText("10", "1", "-0.5"), "w.txt"),
              "w.txt:3: expected a hole azimuth from 0 to 360 degrees in HAZI, found -0.5");
    EXPECT_EQ(refusal(columnText("-3", "1", "20"), "w.txt"),
              "w.txt:3: expected a pad azimuth from 0 to 360 degrees in P1AZ, found -3");
    EXPECT_EQ(refusal(columnText("10", "-1", "20"), "w.txt"),
              "w.txt:3: expected an inclination from 0 to 180 degrees in DEVI, found -1");
}

TEST(AngleRangeTest, OutOfRangeAnglesInLasAreBadInputNamingFileAndLine) {
    EXPECT_EQ(refusal(las("10", "181", "20"), "w.las"),
              "w.las:17: expected an inclination from 0 to 180 degrees in DEVI, found 181");
    EXPECT_EQ(refusal(las("10", "1", "361"), "w.las"),
              "w.las:17: expected a hole azimuth from 0 to 360 degrees in HAZI, found 361");
    EXPECT_EQ(refusal(las("10", "1", "-20"), "w.las"),
              "w.las:17: expected a hole azimuth from 0 to 360 degrees in HAZI, found -20");
    EXPECT_EQ(refusal(las("361", "1", "20"), "w.las"),
              "w.las:17: expected a pad azimuth from 0 to 360 degrees in P1AZ, found 361");
    // Wrapped LAS is read whole, then checked row by row: the file is named.
    const std::string wrapped = refusal(las("10", "181", "20", true), "w.las");
    EXPECT_EQ(wrapped.rfind("w.las:", 0), 0u) << wrapped;
    EXPECT_NE(wrapped.find("expected an inclination from 0 to 180 degrees in DEVI, found 181"),
              std::string::npos)
        << wrapped;
}

TEST(AngleRangeTest, BoundsAndNullsAreAccepted) {
    EXPECT_EQ(refusal(columnText("0", "180", "360"), "w.txt"), "(no error)");
    EXPECT_EQ(refusal(columnText("360", "0", "0"), "w.txt"), "(no error)");
    EXPECT_EQ(refusal(las("-999.25", "-999.25", "-999.25"), "w.las"), "(no error)");
}

}  // namespace

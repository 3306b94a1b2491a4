// appendFixed against std::to_chars, its definition: every value it writes by hand must read
// exactly as to_chars writes it, ties and large values included.
#include "io/number_format.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <random>
#include <string>

#include <gtest/gtest.h>

using caliper3d::io::appendFixed;

namespace {

std::string byToChars(double v, int decimals) {
    char buf[400];
    const char* end =
        std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals).ptr;
    std::string text(buf, static_cast<std::size_t>(end - buf));
    if (text.front() == '-' && text.find_first_not_of("-0.") == std::string::npos) text.erase(0, 1);
    return text;
}

std::string fixed(double v, int decimals) {
    std::string text;
    appendFixed(text, v, decimals);
    return text;
}

}  // namespace

TEST(NumberFormatTest, KnownValuesAndTies) {
    EXPECT_EQ(fixed(215.9, 2), "215.90");
    EXPECT_EQ(fixed(-3.14159, 4), "-3.1416");
    EXPECT_EQ(fixed(0.0, 2), "0.00");
    EXPECT_EQ(fixed(7.0, 0), "7");
    EXPECT_EQ(fixed(0.05, 1), "0.1");  // 0.05 is a little above 1/20 in binary
    // Exact ties round to even, as the exact decimal value is rounded.
    EXPECT_EQ(fixed(0.125, 2), "0.12");
    EXPECT_EQ(fixed(0.375, 2), "0.38");
    EXPECT_EQ(fixed(2.5, 0), "2");
    // 2.675 is 2.67499999... in binary.
    EXPECT_EQ(fixed(2.675, 2), "2.67");
    EXPECT_EQ(fixed(1e20, 2), "100000000000000000000.00");
}

TEST(NumberFormatTest, ADifferenceThatRoundsToNothingHasNoSign) {
    EXPECT_EQ(fixed(-0.004, 2), "0.00");
    EXPECT_EQ(fixed(-0.0, 1), "0.0");
    EXPECT_EQ(fixed(-0.006, 2), "-0.01");
}

TEST(NumberFormatTest, AgreesWithToCharsOnRandomValues) {
    std::mt19937_64 random(25);
    std::uniform_real_distribution<double> exponent(-8.0, 16.0);
    std::uniform_int_distribution<int> decimals(0, 6);
    for (int k = 0; k < 400000; ++k) {
        const double magnitude = std::pow(10.0, exponent(random));
        const double v = (random() & 1 ? -1.0 : 1.0) * magnitude;
        const int d = decimals(random);
        ASSERT_EQ(fixed(v, d), byToChars(v, d)) << v << " with " << d << " decimals";
    }
    // Values on and about the halves of the last decimal, where the rounding turns.
    for (int k = -2000; k <= 2000; ++k)
        for (int d = 0; d <= 4; ++d) {
            const double half = (k + 0.5) / std::pow(10.0, d);
            for (const double v : {half, std::nextafter(half, 1e300), std::nextafter(half, -1e300)})
                ASSERT_EQ(fixed(v, d), byToChars(v, d)) << v << " with " << d << " decimals";
        }
}

TEST(NumberFormatTest, TheBufferFormFitsTheLargestValueAndEndsWhereItsTextEnds) {
    // writeFixed writes into a caller's buffer of kFixedMaxChars: the longest text, the most
    // negative double with the most decimals, must fit, and the end it returns must be the
    // text's own.
    using caliper3d::io::kFixedMaxChars;
    using caliper3d::io::kFixedMaxDecimals;
    using caliper3d::io::writeFixed;
    for (const double v : {-1.7976931348623157e308, 1e300, -123.456, -0.0001, 0.0, 5e-324})
        for (const int d : {0, 2, 6, kFixedMaxDecimals}) {
            char buffer[kFixedMaxChars + 16];
            std::fill(std::begin(buffer), std::end(buffer), '#');
            const char* end = writeFixed(buffer, v, d);
            ASSERT_LE(end - buffer, kFixedMaxChars) << v << " with " << d << " decimals";
            EXPECT_EQ(std::string(static_cast<const char*>(buffer), end), byToChars(v, d))
                << v << " with " << d;
            EXPECT_EQ(buffer[kFixedMaxChars], '#');  // nothing written beyond the room
        }
}

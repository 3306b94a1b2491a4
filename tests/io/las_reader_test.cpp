#include "io/las_reader.h"

#include <cmath>

#include <gtest/gtest.h>

#include "io/parse_error.h"

using namespace caliper3d::io;

namespace {
const char kHeader[] =
    "~Version\n VERS. 2.0 : v\n WRAP. NO : w\n~Well\n NULL. -999.25 : null\n~Curve\n"
    " DEPT.M : depth\n GR.GAPI : gamma\n CALI.IN : caliper\n";
}

TEST(LasReaderTest, ReadsValuesAndCountsDeclaredAndCommonNulls) {
    const std::string text =
        std::string(kHeader) + "~A\n100.0 50.5 8.5\n100.5 -999.25 ERR\n101.0 -9999 ---\n";
    const LasLog log = readLas(text, "t.las", {}, nullptr);
    ASSERT_EQ(log.rowCount(), 3u);
    EXPECT_DOUBLE_EQ(log.curves[1].values[0], 50.5);
    EXPECT_TRUE(std::isnan(log.curves[1].values[1]));
    EXPECT_TRUE(std::isnan(log.curves[1].values[2]));
    EXPECT_TRUE(std::isnan(log.curves[2].values[1]));
    EXPECT_TRUE(std::isnan(log.curves[2].values[2]));
    EXPECT_EQ(log.curves[1].nulls, 2u);
    EXPECT_EQ(log.curves[2].nulls, 2u);
}

TEST(LasReaderTest, DeclaredNullPolicyCountsTextNullsAndKeepsOtherNumbers) {
    LasReadOptions options;
    options.nullPolicy = NullPolicy::Declared;
    const std::string numbers = std::string(kHeader) + "~A\n100.0 -9999 9999\n";
    const LasLog log = readLas(numbers, "t.las", options, nullptr);
    EXPECT_DOUBLE_EQ(log.curves[1].values[0], -9999.0);
    EXPECT_DOUBLE_EQ(log.curves[2].values[0], 9999.0);
    // ERR is not a null under this policy: a value that is not a number, in a curve other
    // than the index, read as null and counted in one warning at its first line.
    const std::string err = std::string(kHeader) + "~A\n100.0 ERR 1\n100.5 ERR 2\n";
    Diagnostics d;
    const LasLog counted = readLas(err, "e.las", options, &d);
    ASSERT_EQ(counted.rowCount(), 2u);
    EXPECT_TRUE(std::isnan(counted.curves[1].values[0]));
    EXPECT_DOUBLE_EQ(counted.curves[2].values[1], 2.0);
    ASSERT_EQ(d.warnings.size(), 1u);
    EXPECT_EQ(d.warnings[0].line, 11u);
    EXPECT_EQ(d.warnings[0].message,
              "curve GR: 2 values are not a number (the first 'ERR'); read as null");
    // In the index it is refused with its place.
    const std::string index = std::string(kHeader) + "~A\nERR 1 1\n";
    try {
        readLas(index, "e.las", options, nullptr);
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 11u);
        EXPECT_EQ(e.column(), 1u);
        EXPECT_NE(std::string(e.what()).find("found 'ERR'"), std::string::npos) << e.what();
    }
}

TEST(LasReaderTest, EveryCommonNullTokenIsNull) {
    for (const char* token : {"ERR", "err", "ERROR", "NaN", "NULL", "N/A", "-", "---", "****"})
        EXPECT_TRUE(isNullToken(token, NullPolicy::Common)) << token;
    EXPECT_TRUE(isNullToken("***", NullPolicy::Declared));
    EXPECT_FALSE(isNullToken("ERR", NullPolicy::Declared));
    EXPECT_FALSE(isNullToken("12", NullPolicy::Common));
    for (const char* number :
         {"-999.25", "999.25", "-9999.25", "9999.25", "-9999", "9999", "-999"}) {
        const std::string text = std::string(kHeader) + "~A\n1 " + number + " 2\n";
        EXPECT_TRUE(std::isnan(readLas(text, "n.las", {}, nullptr).curves[1].values[0])) << number;
    }
}

TEST(LasReaderTest, WrappedRowsSpanLinesAndTruncatedLastRowIsCounted) {
    const std::string text =
        "~V\n VERS. 2.0 :\n WRAP. YES :\n~C\n DEPT.M :\n A. :\n B. :\n C. :\n~A\n1\n 2 3\n 4\n2\n "
        "5 6\n";
    Diagnostics d;
    const LasLog log = readLas(text, "w.las", {}, &d);
    ASSERT_EQ(log.rowCount(), 1u);
    EXPECT_DOUBLE_EQ(log.curves[3].values[0], 4.0);
    EXPECT_EQ(d.warningCount, 1u);
    EXPECT_EQ(d.warnings[0].line, 13u);
}

TEST(LasReaderTest, TruncatedLastLineIsSkippedWithAWarningButAShortLineInsideIsAnError) {
    const std::string last = std::string(kHeader) + "~A\n1 2 3\n2 3\n";
    Diagnostics d;
    EXPECT_EQ(readLas(last, "l.las", {}, &d).rowCount(), 1u);
    EXPECT_EQ(d.warningCount, 1u);
    const std::string inside = std::string(kHeader) + "~A\n1 2 3\n2 3\n3 4 5\n";
    try {
        readLas(inside, "i.las", {}, nullptr);
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 12u);
        EXPECT_NE(std::string(e.what()).find("expected 3 values, found 2"), std::string::npos);
    }
}

TEST(LasReaderTest, DuplicatedMnemonicsAreRenamedAndTextColumnsSkipped) {
    const std::string text =
        "~V\n VERS. 3.0 :\n DLM. COMMA :\n~Log_Definition\n DEPT.M : {F}\n GR.GAPI : {F}\n GR.GAPI "
        ": {F}\n"
        " NOTE. : remark {S}\n~Log_Data\n1.0, 10, 20, hello\n";
    Diagnostics d;
    const LasLog log = readLas(text, "d.las", {}, &d);
    EXPECT_EQ(log.curves[2].mnemonic, "GR:2");
    EXPECT_DOUBLE_EQ(log.curves[2].values[0], 20.0);
    EXPECT_TRUE(log.curves[3].text);
    EXPECT_TRUE(std::isnan(log.curves[3].values[0]));
    EXPECT_EQ(d.warningCount, 2u);
}

// Found by fuzz_las_header: an array index too large for an int was cast
// from a double (undefined behaviour). Such a name is kept whole, not taken
// as an array element.
TEST(LasReaderTest, ArrayIndexOutsideIntRangeIsAPlainName) {
    const std::string text =
        "~Version\n VERS. 3.0 : v\n WRAP. NO : w\n DLM. COMMA : d\n~Log_Definition\n DEPT.M : "
        "depth {F}\n"
        " NMR[4000000000000000000000].MS : echo {AF}\n NMR[2].MS : echo {AF}\n NMR[1.5].MS : echo "
        "{AF}\n"
        " NMR[0].MS : echo {AF}\n~Log_Data | Log_Definition\n1.0,2.0,3.0,4.0,5.0\n";
    const LasLog log = readLas(text, "a.las", {}, nullptr);
    ASSERT_EQ(log.curves.size(), 5u);
    EXPECT_EQ(log.curves[1].arrayIndex, 0);
    EXPECT_EQ(log.curves[1].arrayName, "");
    EXPECT_EQ(log.curves[2].arrayName, "NMR");
    EXPECT_EQ(log.curves[2].arrayIndex, 2);
    EXPECT_EQ(log.curves[3].arrayIndex, 0);
    EXPECT_EQ(log.curves[4].arrayIndex, 0);
    EXPECT_DOUBLE_EQ(log.curves[1].values[0], 2.0);
}

TEST(LasReaderTest, AFileThatDeclaresItsNullOnlyKeepsCommonNullNumbers) {
    const std::string text = std::string(kHeader) +
                             "~P\n NULLS.  DECLARED : only NULL marks a missing value\n" +
                             "~A\n100.0 9999 -999.25\n100.5 -9999 8.5\n";
    const LasLog log = readLas(text, "d.las", {}, nullptr);  // the reader's policy: common
    EXPECT_TRUE(log.header.onlyDeclaredNull);
    EXPECT_DOUBLE_EQ(log.curves[1].values[0], 9999.0);
    EXPECT_DOUBLE_EQ(log.curves[1].values[1], -9999.0);
    EXPECT_TRUE(std::isnan(log.curves[2].values[0]));  // the declared NULL
    EXPECT_EQ(log.curves[1].nulls, 0u);
}

TEST(LasReaderTest, AQuotedStringHoldingTheDelimiterIsOneValue) {
    const std::string text =
        "~Version\n VERS. 3.0 : v\n WRAP. NO : w\n DLM. COMMA : d\n~Log_Definition\n DEPT.M : "
        "depth {F}\n"
        " LITH. : lithology {S}\n GR.GAPI : gamma {F}\n~Log_Data | Log_Definition\n"
        "1.0, \"SAND, SHALY\" ,45.5\n2.0,SAND,46.5\n";
    const LasLog log = readLas(text, "q.las", {}, nullptr);
    ASSERT_EQ(log.rowCount(), 2u);
    EXPECT_DOUBLE_EQ(log.curves[2].values[0], 45.5);
    EXPECT_DOUBLE_EQ(log.curves[2].values[1], 46.5);
    EXPECT_TRUE(std::isnan(log.curves[1].values[0]));
}

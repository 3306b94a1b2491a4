#include "io/las_header.h"

#include <gtest/gtest.h>

#include "io/parse_error.h"

using namespace caliper3d::io;

TEST(LasHeaderTest, SplitsMnemonicUnitValueAndDescription) {
    LasItem item;
    ASSERT_TRUE(splitLasItem(" STRT.M        1670.000000:  START DEPTH", item));
    EXPECT_EQ(item.mnemonic, "STRT");
    EXPECT_EQ(item.unit, "M");
    EXPECT_EQ(item.value, "1670.000000");
    EXPECT_EQ(item.description, "START DEPTH");
    ASSERT_TRUE(splitLasItem(" DATE.  13:00 25-DEC-1988 : LOG DATE", item));
    EXPECT_EQ(item.value, "13:00 25-DEC-1988");  // description after the last colon
    ASSERT_TRUE(splitLasItem("Cond..MS/M                     : Cond.", item));
    EXPECT_EQ(item.mnemonic, "Cond.");
    EXPECT_EQ(item.unit, "MS/M");
    ASSERT_TRUE(splitLasItem("I. Res..OHM-M                  : I. Res.", item));
    EXPECT_EQ(item.mnemonic, "I. Res.");
    EXPECT_EQ(item.unit, "OHM-M");
    ASSERT_TRUE(splitLasItem(" NMR[2] .ms  123 456 789 : NMR Echo Array {AF;5ms} | Run[1]", item));
    EXPECT_EQ(item.mnemonic, "NMR[2]");
    EXPECT_EQ(item.description, "NMR Echo Array {AF;5ms}");
    EXPECT_FALSE(splitLasItem("no separator here", item));
}

TEST(LasHeaderTest, ReadsVersionWrapNullAndDataBounds) {
    const std::string text =
        "~Version\n VERS. 2.0 : v\n WRAP. YES : w\n~Well\n NULL. -999.25 :\n WELL. X-1 : name\n"
        "~Curve\n DEPT.M : d\n R1.IN : r\n~A DEPT R1\n1 2\n3 4\n";
    const LasHeader h = parseLasHeader(text, "t.las", nullptr);
    EXPECT_DOUBLE_EQ(h.version, 2.0);
    EXPECT_TRUE(h.wrap);
    EXPECT_TRUE(h.hasNull);
    EXPECT_DOUBLE_EQ(h.null, -999.25);
    EXPECT_EQ(h.wellItem("WELL")->value, "X-1");
    ASSERT_EQ(h.curves.size(), 2u);
    EXPECT_EQ(h.dataNames, (std::vector<std::string>{"DEPT", "R1"}));
    EXPECT_EQ(h.dataFirstLine, 11u);
    EXPECT_EQ(text.substr(h.dataBegin, h.dataEnd - h.dataBegin), "1 2\n3 4\n");
}

TEST(LasHeaderTest, RefusesNonLasAndUtf16AndBadDelimiter) {
    try {
        parseLasHeader("hello\n~V\n", "x.las", nullptr);
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 1u);
        EXPECT_NE(std::string(e.what()).find("expected a LAS section"), std::string::npos);
    }
    EXPECT_THROW(parseLasHeader(std::string("\xFF\xFE~\0V\0", 6), "u.las", nullptr), ParseError);
    EXPECT_THROW(parseLasHeader("~V\n DLM. PIPE : x\n", "d.las", nullptr), ParseError);
    EXPECT_THROW(parseLasHeader("~C\n DEPT no unit separator\n", "n.las", nullptr), ParseError);
    Diagnostics d;
    parseLasHeader("~V\n VERS 2 no separator\n", "n.las", &d);
    EXPECT_EQ(d.warningCount, 2u);  // the bad line, and no VERS
}

TEST(LasHeaderTest, Las3DefinitionParameterAndDataGroups) {
    const std::string text =
        "~Version\n VERS. 3.0 :\n DLM . COMMA :\n~Log_Parameter\n BS.MM 215.9 : bit\n"
        "~Log_Definition\n DEPT.M : {F}\n R1.MM : {F}\n~Log_Data | Log_Definition\n1,2\n"
        "~Core_Definition\n TOP.M : \n";
    Diagnostics d;
    const LasHeader h = parseLasHeader(text, "t3.las", &d);
    EXPECT_DOUBLE_EQ(h.version, 3.0);
    EXPECT_EQ(h.delimiter, ',');
    EXPECT_EQ(h.parameter("BS")->value, "215.9");
    EXPECT_EQ(h.curves.size(), 2u);
    EXPECT_TRUE(h.dataNames.empty());
    EXPECT_EQ(text.substr(h.dataBegin, h.dataEnd - h.dataBegin), "1,2\n");
    EXPECT_EQ(d.warningCount, 1u);  // the core group is skipped, and said so
}

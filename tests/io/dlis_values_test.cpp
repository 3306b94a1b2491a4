// The representation codes of RP66 v1 against the standard's own examples (Appendix B
// gives 153 and -153 in every numeric code), and explicitly formatted sets built byte by
// byte: template defaults, absent and invariant attributes.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/dlis/dlis_cursor.h"
#include "io/dlis/dlis_reader.h"
#include "io/parse_error.h"

namespace caliper3d::io::dlis {
namespace {

using Bytes = std::vector<unsigned char>;

double decode(int code, const Bytes& b) {
    return decodeNumber(code, b.data());
}

TEST(DlisValuesTest, EveryNumericCodeDecodesTheStandardsExamples) {
    EXPECT_DOUBLE_EQ(decode(kFSHORT, {0x4C, 0x88}), 153.0);
    EXPECT_DOUBLE_EQ(decode(kFSHORT, {0xB3, 0x88}), -153.0);
    EXPECT_DOUBLE_EQ(decode(kFSHORT, {0x7F, 0xF0}), 1.0 - 1.0 / 2048.0);
    EXPECT_DOUBLE_EQ(decode(kFSINGL, {0x43, 0x19, 0x00, 0x00}), 153.0);
    EXPECT_DOUBLE_EQ(decode(kFSINGL, {0xC3, 0x19, 0x00, 0x00}), -153.0);
    EXPECT_DOUBLE_EQ(decode(kISINGL, {0x42, 0x99, 0x00, 0x00}), 153.0);
    EXPECT_DOUBLE_EQ(decode(kISINGL, {0xC2, 0x99, 0x00, 0x00}), -153.0);
    EXPECT_DOUBLE_EQ(decode(kISINGL, {0xC2, 0x76, 0xA0, 0x00}), -118.625);
    EXPECT_DOUBLE_EQ(decode(kVSINGL, {0x19, 0x44, 0x00, 0x00}), 153.0);
    EXPECT_DOUBLE_EQ(decode(kVSINGL, {0x19, 0xC4, 0x00, 0x00}), -153.0);
    EXPECT_DOUBLE_EQ(decode(kVSINGL, {0x00, 0x00, 0x00, 0x00}), 0.0);
    EXPECT_TRUE(std::isnan(decode(kVSINGL, {0x00, 0x80, 0x00, 0x00})));  // reserved
    EXPECT_DOUBLE_EQ(decode(kFDOUBL, {0x40, 0x63, 0x20, 0, 0, 0, 0, 0}), 153.0);
    EXPECT_DOUBLE_EQ(decode(kFDOUBL, {0xC0, 0x63, 0x20, 0, 0, 0, 0, 0}), -153.0);
    EXPECT_DOUBLE_EQ(decode(kSSHORT, {0xA7}), -89.0);
    EXPECT_DOUBLE_EQ(decode(kSNORM, {0xFF, 0x67}), -153.0);
    EXPECT_DOUBLE_EQ(decode(kSLONG, {0xFF, 0xFF, 0xFF, 0x67}), -153.0);
    EXPECT_DOUBLE_EQ(decode(kUSHORT, {0xA7}), 167.0);
    EXPECT_DOUBLE_EQ(decode(kUNORM, {0xFF, 0x67}), 65383.0);
    EXPECT_DOUBLE_EQ(decode(kULONG, {0xFF, 0xFF, 0xFF, 0x67}), 4294967143.0);
    // A compound's first component: FSING1 value then bound, CSINGL real then imaginary.
    EXPECT_DOUBLE_EQ(decode(kFSING1, {0x43, 0x19, 0, 0, 0x3F, 0x80, 0, 0}), 153.0);
    EXPECT_DOUBLE_EQ(decode(kCSINGL, {0xC3, 0x19, 0, 0, 0x3F, 0x80, 0, 0}), -153.0);
    EXPECT_TRUE(std::isnan(decode(kIDENT, {0x00})));
}

TEST(DlisValuesTest, VariableCodesReadTheirLengthsAndNeverPastTheEnd) {
    const Bytes b = {0x2E, 0x81, 0x00, 0xC1, 0x00, 0x00, 0x00, 0x03, 'A', 'B', 'C'};
    Cursor c(b.data(), b.size());
    EXPECT_EQ(c.uvari(), 46u);
    EXPECT_EQ(c.uvari(), 256u);
    EXPECT_EQ(c.uvari(), 16777216u);
    EXPECT_EQ(c.ident(), "ABC");
    EXPECT_TRUE(c.atEnd());
    const Bytes cut = {0x05, 'A', 'B'};
    Cursor short1(cut.data(), cut.size());
    EXPECT_THROW(short1.ident(), BodyError);
    const Bytes cutUvari = {0xC0, 0x00};
    Cursor short2(cutUvari.data(), cutUvari.size());
    EXPECT_THROW(short2.uvari(), BodyError);
}

TEST(DlisValuesTest, DatesNamesAndReferencesDecodeWhole) {
    // 1987-04-19 21:20:15.620 local daylight savings (the standard's DTIME example).
    const Bytes dtime = {87, 0x14, 19, 21, 20, 15, 0x02, 0x6C};
    Cursor d(dtime.data(), dtime.size());
    EXPECT_EQ(std::get<std::string>(d.value(kDTIME)),
              "1987-04-19 21:20:15.620 local daylight savings");
    const Bytes badMonth = {87, 0x0D, 19, 21, 20, 15, 0x02, 0x6C};
    Cursor bad(badMonth.data(), badMonth.size());
    EXPECT_THROW(bad.value(kDTIME), BodyError);
    // OBJREF: type "CHANNEL", name origin 2 copy 0 "GR".
    const Bytes ref = {7, 'C', 'H', 'A', 'N', 'N', 'E', 'L', 2, 0, 2, 'G', 'R'};
    Cursor r(ref.data(), ref.size());
    const ObjectRef o = std::get<ObjectRef>(r.value(kOBJREF));
    EXPECT_EQ(o.type, "CHANNEL");
    EXPECT_EQ(o.name.origin, 2u);
    EXPECT_EQ(o.name.id, "GR");
    const Bytes unknown = {0x00};
    Cursor u(unknown.data(), unknown.size());
    EXPECT_THROW(u.value(28), BodyError);
    EXPECT_EQ(repCodeName(kFSINGL), "FSINGL");
    EXPECT_EQ(repCodeSize(kFDOUB2), 24u);
    EXPECT_EQ(repCodeSize(kASCII), 0u);
}

// A file of one visible record holding one logical record segment per body given.
std::string oneVisibleRecord(const std::vector<std::pair<int, Bytes>>& records) {
    std::string label = "   1V1.00RECORD08192" + std::string(60, ' ');
    std::string vr;
    for (const auto& [type, body] : records) {
        // Segments are of even length: an odd body takes one pad byte (its count, 1).
        const bool padded = body.size() % 2 != 0;
        const std::size_t length = 4 + body.size() + (padded ? 1 : 0);
        vr += static_cast<char>(length >> 8);
        vr += static_cast<char>(length & 0xFF);
        vr += static_cast<char>((type >= 0 ? 0x80 : 0x00) | (padded ? 0x01 : 0x00));
        vr += static_cast<char>(type >= 0 ? type : 0);
        for (std::size_t i = 0; i < body.size(); ++i) vr += static_cast<char>(body[i]);
        if (padded) vr += static_cast<char>(1);
    }
    const std::size_t total = vr.size() + 4;
    std::string head;
    head += static_cast<char>(total >> 8);
    head += static_cast<char>(total & 0xFF);
    head += static_cast<char>(0xFF);
    head += static_cast<char>(0x01);
    return label + head + vr;
}

void ident(Bytes& b, const std::string& s) {
    b.push_back(static_cast<unsigned char>(s.size()));
    b.insert(b.end(), s.begin(), s.end());
}

TEST(DlisValuesTest, ObjectsTakeTheTemplatesDefaultsAbsentAndInvariantAttributes) {
    Bytes header = {0xF0};  // SET with type
    ident(header, "FILE-HEADER");
    header.push_back(0x30);  // template: ATTRIB with label
    ident(header, "ID");
    header.push_back(0x70);  // OBJECT with name
    header.insert(header.end(), {0, 0});
    ident(header, "0");
    header.push_back(0x21);  // ATTRIB: value only (IDENT by default)
    ident(header, "RUN ONE");

    Bytes params = {0xF0};
    ident(params, "PARAMETER");
    params.push_back(0x30);
    ident(params, "LONG-NAME");
    params.push_back(0x37);  // label, code, units, value: default VALUES 8.5 in (FSINGL)
    ident(params, "VALUES");
    params.push_back(kFSINGL);
    ident(params, "in");
    params.insert(params.end(), {0x41, 0x08, 0x00, 0x00});
    params.push_back(0x54);  // invariant attribute: label and code, no value
    ident(params, "ZONES");
    params.push_back(kOBNAME);
    // Object BS: long name given, VALUES from the template.
    params.push_back(0x70);
    params.insert(params.end(), {0, 0});
    ident(params, "BS");
    params.push_back(0x21);
    ident(params, "Bit Size");
    // Object MDEC: long name absent, VALUES 2.5 deg given with its units.
    params.push_back(0x70);
    params.insert(params.end(), {0, 0});
    ident(params, "MDEC");
    params.push_back(0x00);  // ABSATR
    params.push_back(0x23);  // units and value
    ident(params, "deg");
    params.insert(params.end(), {0x40, 0x20, 0x00, 0x00});

    const std::string file = oneVisibleRecord({{0, header}, {5, params}});
    Diagnostics d;
    const DlisIndex index = indexDlis(file, "set.dlis", &d);
    ASSERT_EQ(index.files.size(), 1u);
    const LogicalFile& f = index.files.front();
    EXPECT_EQ(f.id, "RUN ONE");
    ASSERT_EQ(f.parameters.size(), 2u);
    const Parameter& bs = f.parameters[0];
    EXPECT_EQ(bs.name.id, "BS");
    EXPECT_EQ(bs.longName, "Bit Size");
    EXPECT_EQ(bs.units, "in");
    ASSERT_EQ(bs.values.size(), 1u);
    EXPECT_DOUBLE_EQ(std::get<double>(bs.values[0]), 8.5);
    const Parameter& mdec = f.parameters[1];
    EXPECT_EQ(mdec.longName, "");
    EXPECT_EQ(mdec.units, "deg");
    EXPECT_DOUBLE_EQ(std::get<double>(mdec.values.at(0)), 2.5);
    const std::vector<const Object*> objects = f.objects("PARAMETER");
    ASSERT_EQ(objects.size(), 2u);
    EXPECT_EQ(objects[1]->attribute("LONG-NAME"), nullptr);  // absent
    const Attribute* zones = objects[0]->attribute("ZONES");
    ASSERT_NE(zones, nullptr);
    EXPECT_TRUE(zones->invariant);
    EXPECT_EQ(zones->repCode, kOBNAME);
    EXPECT_EQ(d.warningCount, 0u);
}

TEST(DlisValuesTest, WhatIsNotDlisIsRefusedNamingTheFileAndByte) {
    EXPECT_FALSE(looksLikeDlis("~Version\nVERS. 2.0\n"));
    EXPECT_TRUE(looksLikeDlis("   1V1.00RECORD08192" + std::string(60, ' ')));
    try {
        indexDlis("~Version information\n", "text.las", nullptr);
        FAIL() << "text read as DLIS";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.file(), "text.las");
        EXPECT_NE(e.message().find("byte 0"), std::string::npos) << e.message();
        EXPECT_NE(e.message().find("storage unit label"), std::string::npos) << e.message();
    }
    // A label and nothing after it.
    try {
        indexDlis("   1V1.00RECORD08192" + std::string(60, ' '), "label.dlis", nullptr);
        FAIL() << "a bare label read";
    } catch (const ParseError& e) {
        EXPECT_NE(e.message().find("byte 80"), std::string::npos) << e.message();
    }
}

}  // namespace
}  // namespace caliper3d::io::dlis

// The test DLIS writer (tests/support/dlis_writer.h) against RP66 v1 itself: the bytes of
// values whose encodings the standard spells out, and the layout of what it writes with
// every segment option (the visible records and segments must add up to the file).
#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "support/dlis_fixtures.h"
#include "support/dlis_writer.h"

namespace dlis = caliper3d::test::dlis;

namespace {

std::string hex(const std::string& bytes) {
    static const char* digits = "0123456789ABCDEF";
    std::string out;
    for (unsigned char c : bytes) {
        out += digits[c >> 4];
        out += digits[c & 15];
    }
    return out;
}

std::string number(int code, double v) {
    std::string out;
    dlis::putNumber(out, code, v);
    return hex(out);
}

}  // namespace

TEST(DlisWriterTest, NumbersTakeTheBytesOfAppendixB) {
    // IEEE: 1.0f = 3F800000; IBM: 1.0 = 0.1 (hex) x 16^1 = 41100000, -118.625 = C276A000 (the
    // classic IBM example); VAX F: 1.0 = 0.1 (binary) x 2^1, exponent 129, words swapped.
    EXPECT_EQ(number(dlis::FSINGL, 1.0), "3F800000");
    EXPECT_EQ(number(dlis::ISINGL, 1.0), "41100000");
    EXPECT_EQ(number(dlis::ISINGL, -118.625), "C276A000");
    EXPECT_EQ(number(dlis::VSINGL, 1.0), "80400000");
    EXPECT_EQ(number(dlis::VSINGL, -0.5), "00C00000");
    // FSHORT: 12-bit fraction then 4-bit exponent: 1.0 = 1024/2048 x 2^1; -1.0 = -2048/2048.
    EXPECT_EQ(number(dlis::FSHORT, 1.0), "4001");
    EXPECT_EQ(number(dlis::FSHORT, -1.0), "8000");
    EXPECT_EQ(number(dlis::FDOUBL, -2.0), "C000000000000000");
    EXPECT_EQ(number(dlis::SSHORT, -1), "FF");
    EXPECT_EQ(number(dlis::SNORM, -2), "FFFE");
    EXPECT_EQ(number(dlis::SLONG, 258), "00000102");
    EXPECT_EQ(number(dlis::UNORM, 513), "0201");
    // UVARI: 1, 2 or 4 bytes by the two high bits.
    EXPECT_EQ(number(dlis::UVARI, 127), "7F");
    EXPECT_EQ(number(dlis::UVARI, 128), "8080");
    EXPECT_EQ(number(dlis::UVARI, 16384), "C0004000");
    std::string wide;
    dlis::putUvari(wide, 5, 4);
    EXPECT_EQ(hex(wide), "C0000005");
    EXPECT_THROW(number(dlis::USHORT, 256), std::invalid_argument);
    EXPECT_THROW(number(dlis::ASCII, 1), std::invalid_argument);
}

TEST(DlisWriterTest, NamesTextsAndTimes) {
    std::string out;
    dlis::putObname(out, {200, 3, "TDEP"});
    EXPECT_EQ(hex(out), "80C8030454444550");
    out.clear();
    dlis::putAscii(out, "ab");
    EXPECT_EQ(hex(out), "026162");
    out.clear();
    // 1987-04-19 21:20:15.620 local daylight savings: 87, 0x14, 19, 21, 20, 15, 620.
    dlis::putDtime(out, "1987-04-19 21:20:15.620 local daylight savings");
    EXPECT_EQ(hex(out), "57141315140F026C");
}

TEST(DlisWriterTest, ChecksumFoldsTheCarryAndRotates) {
    EXPECT_EQ(dlis::checksum16(std::string("\x01\x00", 2)), 2);
    EXPECT_EQ(dlis::checksum16(std::string("\x01\x00\x01\x00", 4)), 6);
    // 0xFFFF rotated stays 0xFFFF; + 2 carries out, folded back to 2, rotated to 4.
    EXPECT_EQ(dlis::checksum16(std::string("\xFF\xFF\x02\x00", 4)), 4);
}

TEST(DlisWriterTest, SetsWriteTheirComponentDescriptors) {
    dlis::Set s;
    s.type = "CHANNEL";
    s.templ = {dlis::attr("UNITS", dlis::texts(dlis::UNITS, {}))};
    s.objects.push_back({{1, 0, "A"}, {dlis::absentAttr()}});
    s.objects.push_back({{1, 0, "B"}, {dlis::valueOnly(dlis::texts(dlis::UNITS, {"m"}))}});
    // SET with type (F0), "CHANNEL"; template ATTRIB label + code (34) "UNITS" code 27;
    // OBJECT (70) 1 0 "A" ABSATR (00); OBJECT 1 0 "B", ATTRIB value only (21) "m".
    EXPECT_EQ(hex(dlis::encodeSet(s)), "F007" + hex("CHANNEL") + "3405" + hex("UNITS") + "1B" +
                                           "7001000141" + "00" + "7001000142" + "21016D");
}

TEST(DlisWriterTest, EveryLayoutOptionAddsUp) {
    dlis::SixArmShape shape;
    shape.rows = 120;
    const std::vector<dlis::LogicalFileSpec> files = dlis::twoRunLogs(shape, shape);
    struct Variant {
        const char* name;
        dlis::WriteOptions options;
    };
    std::vector<Variant> variants(8);
    variants[0].name = "plain";
    variants[1].name = "padding";
    variants[1].options.padAlways = true;
    variants[2].name = "checksums";
    variants[2].options.checksums = true;
    variants[3].name = "trailing length";
    variants[3].options.trailingLength = true;
    variants[4].name = "split segments and visible records";
    variants[4].options.segmentBody = 23;
    variants[4].options.visibleRecordLength = 250;
    variants[5].name = "tape image";
    variants[5].options.tapeImage = true;
    variants[5].options.tapeRecordLength = 1000;
    variants[6].name = "leading garbage";
    variants[6].options.leadingGarbage = std::string(37, '\x5A');
    variants[7].name = "all at once, encrypted record";
    variants[7].options = variants[4].options;
    variants[7].options.padAlways = variants[7].options.checksums = true;
    variants[7].options.trailingLength = variants[7].options.encryptedRecord = true;
    variants[7].options.wideUvari = true;
    // Records: per file a header and an origin; the six-arm runs a parameter, channel and
    // frame set and one frame data record per row; the gamma-ray file 50 rows.
    const std::size_t records = 2 + 2 + 50 + 2 * (5 + shape.rows);
    for (const Variant& v : variants) {
        const std::string bytes = dlis::writeDlis(files, v.options);
        const dlis::Layout layout = dlis::checkLayout(bytes);
        EXPECT_EQ(layout.error, "") << v.name;
        const std::size_t encrypted = v.options.encryptedRecord ? files.size() : 0;
        EXPECT_EQ(layout.records, records + encrypted) << v.name;
        if (v.options.segmentBody)
            EXPECT_GT(layout.segments, 2 * layout.records) << v.name;
        else  // one record cut at each visible record's end at most
            EXPECT_LE(layout.segments, layout.records + layout.visibleRecords) << v.name;
        if (v.options.visibleRecordLength < 8192) {
            EXPECT_GT(layout.visibleRecords, bytes.size() / 250) << v.name;
        }
    }
}

TEST(DlisWriterTest, CutBytesAreCaughtByTheLayoutCheck) {
    dlis::SixArmShape shape;
    shape.rows = 10;
    const std::string bytes = dlis::writeDlis({dlis::sixArmLog(shape)});
    EXPECT_EQ(dlis::checkLayout(bytes).error, "");
    EXPECT_NE(dlis::checkLayout(bytes.substr(0, bytes.size() - 3)).error, "");
}

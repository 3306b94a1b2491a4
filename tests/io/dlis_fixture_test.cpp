// The DLIS reader end to end on logs the test writer builds from analytic hole shapes
// (tests/support/dlis_fixtures.h): arms, depths in their units, radii, orientation, bit
// size, well name, casing, location, logical file choice, every segment layout, an
// encrypted record, every numeric code, and files cut short.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/atomic_output.h"
#include "io/casing_program.h"
#include "io/dlis/dlis_reader.h"
#include "io/log_reader.h"
#include "io/parse_error.h"
#include "io/well_location.h"
#include "support/dlis_fixtures.h"
#include "support/dlis_writer.h"
#include "test_support.h"

using caliper3d::io::describeLog;
using caliper3d::io::loadCaliperLog;
using caliper3d::io::LoadedLog;
using caliper3d::io::LogInfo;
using caliper3d::io::ParseError;
using caliper3d::io::ReadOptions;
using caliper3d::io::SectionTable;
using caliper3d::test::scratch;
namespace dlis = caliper3d::test::dlis;

namespace {

std::string write(const std::string& name, const std::vector<dlis::LogicalFileSpec>& files,
                  const dlis::WriteOptions& options = {}) {
    std::string path = scratch(name).string();
    dlis::writeDlisFile(path, files, options);
    return path;
}

std::string writeBytes(const std::string& name, const std::string& bytes) {
    std::string path = scratch(name).string();
    caliper3d::io::AtomicOutput out(path);  // whole, for tests that run at once
    out.stream().write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.commit();
    return path;
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

std::string warnings(const caliper3d::io::Diagnostics& d) {
    std::string out;
    for (const auto& w : d.warnings) out += "\n  warning: " + w.message;
    return out;
}

bool anyWarning(const caliper3d::io::Diagnostics& d, const std::string& word) {
    for (const auto& w : d.warnings)
        if (lower(w.message).find(word) != std::string::npos) return true;
    return false;
}

const caliper3d::io::ExtraCurve* extra(const SectionTable& t, const std::string& name) {
    for (const auto& e : t.extraCurves)
        if (e.mnemonic == name) return &e;
    return nullptr;
}

// The index of the file at `path`, its warnings into `d`.
caliper3d::io::dlis::DlisIndex indexFile(const std::string& path, caliper3d::io::Diagnostics& d) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return caliper3d::io::dlis::indexDlis(bytes, path, &d);
}

// The six-arm known answers, row by row.
void expectSixArm(const SectionTable& t, const dlis::SixArmShape& s) {
    ASSERT_EQ(t.armCount, 6);
    ASSERT_EQ(t.rowCount(), s.rows);
    ASSERT_EQ(t.p1az_deg.size(), s.rows);
    ASSERT_EQ(t.devi_deg.size(), s.rows);
    ASSERT_EQ(t.hazi_deg.size(), s.rows);
    for (std::size_t i = 0; i < s.rows; ++i) {
        EXPECT_NEAR(t.depth_m[i], s.depth_m(i), 1e-6) << "row " << i;
        for (int k = 1; k <= 6; ++k)  // FSINGL inches: 1e-7 relative
            EXPECT_NEAR(t.radii(i)[k - 1], s.radius_mm(i, k), 1e-3) << "row " << i << " arm " << k;
        EXPECT_NEAR(t.p1az_deg[i], s.p1az_deg(i), 1e-4) << "row " << i;
        EXPECT_NEAR(t.devi_deg[i], s.devi_deg, 1e-5);
        EXPECT_NEAR(t.hazi_deg[i], s.hazi_deg, 1e-5);
        if (::testing::Test::HasFailure()) return;
    }
    ASSERT_EQ(t.bitSize_mm.size(), s.rows);
    EXPECT_NEAR(t.bitSize_mm.front(), s.bitSize_in * 25.4, 1e-9);
}

// The same rows and values (bit for bit) in two tables.
void expectSameTable(const SectionTable& a, const SectionTable& b, const std::string& what) {
    EXPECT_EQ(a.armCount, b.armCount) << what;
    EXPECT_EQ(a.depth_m, b.depth_m) << what;
    EXPECT_EQ(a.radius_mm, b.radius_mm) << what;
    EXPECT_EQ(a.p1az_deg, b.p1az_deg) << what;
    EXPECT_EQ(a.devi_deg, b.devi_deg) << what;
    EXPECT_EQ(a.hazi_deg, b.hazi_deg) << what;
    EXPECT_EQ(a.bitSize_mm, b.bitSize_mm) << what;
    EXPECT_EQ(a.wellName, b.wellName) << what;
}

}  // namespace

class DlisSixArmDepthUnits : public ::testing::TestWithParam<const char*> {};

TEST_P(DlisSixArmDepthUnits, ReadsArmsDepthsRadiiOrientationAndBitSize) {
    dlis::SixArmShape shape;
    shape.depthUnits = GetParam();
    const std::string path =
        write(std::string("dlis_six_arm_") + (shape.depthUnits == "0.1 in" ? "tenth" : GetParam()) +
                  ".dlis",
              {dlis::sixArmLog(shape)});
    const LoadedLog log = loadCaliperLog(path, ReadOptions{});
    expectSixArm(log.table, shape);
    EXPECT_EQ(log.info.wellName, shape.wellName);
    EXPECT_EQ(log.info.arms, 6);
    EXPECT_EQ(log.info.rows, shape.rows);
    EXPECT_NEAR(log.info.top_m, shape.depth_m(0), 1e-6);
    EXPECT_NEAR(log.info.bottom_m, shape.depth_m(shape.rows - 1), 1e-6);
    EXPECT_NEAR(log.info.bitSize_mm, 215.9, 1e-9);
    EXPECT_EQ(log.info.format.rfind("DLIS", 0), 0u) << log.info.format;
}

INSTANTIATE_TEST_SUITE_P(DlisFixtureTest, DlisSixArmDepthUnits,
                         ::testing::Values("0.1 in", "m", "ft"));

TEST(DlisFixtureTest, DescribeListsWhatLoadReads) {
    dlis::SixArmShape shape;
    const std::string path = write("dlis_six_arm_describe.dlis", {dlis::sixArmLog(shape)});
    const LogInfo info = describeLog(path, ReadOptions{});
    EXPECT_EQ(info.wellName, shape.wellName);
    EXPECT_EQ(info.rows, shape.rows);
    EXPECT_EQ(info.arms, 6);
    EXPECT_NEAR(info.top_m, shape.depth_m(0), 1e-6);
    EXPECT_NEAR(info.bitSize_mm, 215.9, 1e-9);
    const std::string text = caliper3d::io::formatLogInfo(info);
    for (const char* name : {"TDEP", "RAD1", "RAD6", "P1AZ", "DEVI", "HAZI"})
        EXPECT_NE(text.find(name), std::string::npos) << name << "\n" << text;
    EXPECT_NE(text.find(shape.wellName), std::string::npos) << text;
}

TEST(DlisFixtureTest, EveryNumericCodeReadsItsValues) {
    dlis::SixArmShape shape;
    shape.rows = 97;  // every value codeValue() takes
    const std::string path = write("dlis_every_code.dlis", {dlis::everyCodeLog(shape)});
    const LoadedLog log = loadCaliperLog(path, ReadOptions{});
    expectSixArm(log.table, shape);
    const LogInfo info = describeLog(path, ReadOptions{});
    std::string listed = caliper3d::io::formatLogInfo(info);
    for (const std::string& d : info.details) listed += d + "\n";
    for (int code = 1; code <= 18; ++code) {
        const auto* e = extra(log.table, "V_" + dlis::codeName(code));
        EXPECT_NE(listed.find("V_" + dlis::codeName(code)), std::string::npos) << listed;
        ASSERT_NE(e, nullptr) << dlis::codeName(code);
        ASSERT_EQ(e->values.size(), shape.rows);
        for (std::size_t i = 0; i < shape.rows; ++i)
            ASSERT_EQ(e->values[i], dlis::codeValue(code, i))
                << dlis::codeName(code) << " row " << i;
    }
}

TEST(DlisFixtureTest, RadiiInEveryFloatCodeGiveTheSameHole) {
    dlis::SixArmShape shape;
    shape.rows = 50;
    for (int code :
         {dlis::FDOUBL, dlis::ISINGL, dlis::VSINGL, dlis::FSING1, dlis::FDOUB2, dlis::CSINGL}) {
        dlis::LogicalFileSpec f = dlis::sixArmLog(shape);
        f.frames[0] = dlis::sixArmFrame(shape, code);
        const std::string path = write("dlis_radius_code.dlis", {f});
        const LoadedLog log = loadCaliperLog(path, ReadOptions{});
        ASSERT_EQ(log.table.armCount, 6) << dlis::codeName(code);
        for (std::size_t i = 0; i < shape.rows; ++i)
            for (int k = 1; k <= 6; ++k)
                ASSERT_NEAR(log.table.radii(i)[k - 1], shape.radius_mm(i, k), 2e-3)
                    << dlis::codeName(code) << " row " << i << " arm " << k;
    }
}

TEST(DlisFixtureTest, FortyFingerArrayIsFortyRadiiSortedDownwards) {
    dlis::FingerShape shape;
    const std::string path = write("dlis_forty_finger.dlis", {dlis::fingerLog(shape)});
    const LoadedLog log = loadCaliperLog(path, ReadOptions{});
    const SectionTable& t = log.table;
    ASSERT_EQ(t.armCount, 40);
    ASSERT_EQ(t.rowCount(), shape.rows);
    for (std::size_t i = 0; i < shape.rows; ++i) {
        // Logged upwards (DECREASING): read back deepest last.
        EXPECT_NEAR(t.depth_m[i], shape.depth_m(shape.rows - 1 - i), 1e-9) << "row " << i;
        for (int k = 1; k <= 40; ++k)
            ASSERT_NEAR(t.radii(i)[k - 1], shape.radius_mm(k), 1e-4)
                << "row " << i << " finger " << k;
    }
    EXPECT_TRUE(t.p1az_deg.empty());
    EXPECT_EQ(log.info.wellName, shape.wellName);
    EXPECT_NE(log.info.armSource.find("FING[1]"), std::string::npos) << log.info.armSource;
    const auto* gr = extra(t, "GR");
    ASSERT_NE(gr, nullptr);
    EXPECT_EQ(gr->values[0], static_cast<double>((shape.rows - 1) % 150));
}

TEST(DlisFixtureTest, PadImagerPairsAreEightArmsAndTheImageIsListedNotRead) {
    dlis::PadImagerShape shape;
    const std::string path = write("dlis_pad_imager.dlis", {dlis::padImagerLog(shape)});
    const LoadedLog log = loadCaliperLog(path, ReadOptions{});
    const SectionTable& t = log.table;
    ASSERT_EQ(t.armCount, 8);
    ASSERT_EQ(t.rowCount(), shape.rows);
    ASSERT_EQ(t.p1az_deg.size(), shape.rows);
    for (std::size_t i = 0; i < shape.rows; ++i) {
        EXPECT_NEAR(t.depth_m[i], shape.depth_m(i), 1e-9);
        EXPECT_NEAR(t.p1az_deg[i], shape.p1az_deg(i), 1e-9);
        EXPECT_NEAR(t.devi_deg[i], 2.0, 1e-6);
        EXPECT_NEAR(t.hazi_deg[i], 75.0, 1e-6);
        // Pad k and pad k + 4 share pair (k - 1) mod 4 + 1: each its half.
        for (int k = 1; k <= 8; ++k)
            ASSERT_NEAR(t.radii(i)[k - 1], shape.diameter_mm(i, (k - 1) % 4 + 1) / 2.0, 1e-3)
                << "row " << i << " arm " << k;
    }
    for (const auto& e : t.extraCurves)
        EXPECT_EQ(e.mnemonic.rfind("IMG", 0), std::string::npos) << e.mnemonic;
    const LogInfo info = describeLog(path, ReadOptions{});
    std::string listed = caliper3d::io::formatLogInfo(info);
    for (const std::string& d : info.details) listed += d + "\n";
    EXPECT_NE(listed.find("IMG"), std::string::npos) << listed;
    EXPECT_EQ(info.arms, 8);
}

TEST(DlisFixtureTest, LogicalFileChoice) {
    dlis::SixArmShape run1, run2;
    run1.top_m = 1000.0;
    run1.rows = 300;
    run2.top_m = 1500.0;
    run2.rows = 200;
    run2.depthUnits = "m";
    const std::string path = write("dlis_two_runs.dlis", dlis::twoRunLogs(run1, run2));
    // The first logical file holds no caliper: the default is the first that does.
    ReadOptions options;
    expectSixArm(loadCaliperLog(path, options).table, run1);
    options.logicalFile = 2;
    expectSixArm(loadCaliperLog(path, options).table, run1);
    options.logicalFile = 3;
    expectSixArm(loadCaliperLog(path, options).table, run2);
    const LogInfo third = describeLog(path, options);
    EXPECT_NEAR(third.top_m, 1500.0, 1e-9);
    for (int wrong : {4, 40}) {
        options.logicalFile = wrong;
        try {
            (void)loadCaliperLog(path, options);
            ADD_FAILURE() << "--file " << wrong << " read";
        } catch (const std::exception& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(path), std::string::npos) << message;
            EXPECT_NE(message.find(std::to_string(wrong)), std::string::npos) << message;
            EXPECT_NE(message.find('3'), std::string::npos) << "how many there are: " << message;
        }
    }
    options.logicalFile = 1;  // the gamma-ray file: no caliper curves
    EXPECT_THROW((void)caliper3d::io::readCaliperLog(path, options, nullptr), std::exception);
}

TEST(DlisFixtureTest, ParametersGiveCasingDeclinationAndLocation) {
    dlis::SixArmShape shape;
    dlis::WellParameters p;
    const std::string path =
        write("dlis_parameters.dlis", {dlis::sixArmLogWithParameters(shape, p)});
    const LoadedLog log = loadCaliperLog(path, ReadOptions{});
    expectSixArm(log.table, shape);
    ASSERT_EQ(log.table.casing.size(), 1u);
    const auto& c = log.table.casing.front();
    EXPECT_NEAR(c.bottom_m, p.casingShoe_m, 1e-9);
    EXPECT_NEAR(c.size_mm, p.casingSize_in * 25.4, 1e-4);
    EXPECT_NEAR(c.weight_kgPerM, p.casingWeight_lbPerFt * 0.45359237 / 0.3048, 1e-3);
    const double id = caliper3d::io::nominalCasingId_mm(c.size_mm, c.weight_kgPerM);
    ASSERT_TRUE(std::isfinite(id));  // 9 5/8 in 47 lb/ft is in the API 5CT table
    EXPECT_NEAR(c.innerDiameter_mm, id, 1e-9);
    EXPECT_EQ(c.type, p.casingType);
    const LogInfo& info = log.info;
    EXPECT_NEAR(info.location.latitude_deg, p.latitude_deg, 1e-9);
    EXPECT_NEAR(info.location.longitude_deg, p.longitude_deg, 1e-9);
    EXPECT_NEAR(info.location.referenceElevation_m, p.kellyBushing_m, 1e-9);
    EXPECT_EQ(info.casing.size(), 1u);
    // The header alone, as a field is placed from it (io::readWellLocationOf).
    const caliper3d::io::WellLocation head = caliper3d::io::readWellLocationOf(path, nullptr);
    EXPECT_NEAR(head.latitude_deg, p.latitude_deg, 1e-9);
    EXPECT_NEAR(head.longitude_deg, p.longitude_deg, 1e-9);
    EXPECT_NEAR(head.referenceElevation_m, p.kellyBushing_m, 1e-9);
}

TEST(DlisFixtureTest, EverySegmentLayoutGivesTheSameTable) {
    dlis::SixArmShape shape;
    shape.rows = 250;
    const std::vector<dlis::LogicalFileSpec> files = {dlis::sixArmLog(shape)};
    const LoadedLog plain = loadCaliperLog(write("dlis_layout_plain.dlis", files), ReadOptions{});
    expectSixArm(plain.table, shape);
    struct Variant {
        std::string name;
        dlis::WriteOptions options;
    };
    std::vector<Variant> variants;
    auto add = [&](const std::string& name, auto change) {
        Variant v{name, {}};
        change(v.options);
        variants.push_back(v);
    };
    add("padding", [](dlis::WriteOptions& o) { o.padAlways = true; });
    add("checksums", [](dlis::WriteOptions& o) { o.checksums = true; });
    add("trailing_length", [](dlis::WriteOptions& o) { o.trailingLength = true; });
    add("split_segments", [](dlis::WriteOptions& o) { o.segmentBody = 17; });
    add("small_visible_records", [](dlis::WriteOptions& o) { o.visibleRecordLength = 128; });
    add("tape_image", [](dlis::WriteOptions& o) { o.tapeImage = true; });
    add("tape_image_small_records", [](dlis::WriteOptions& o) {
        o.tapeImage = true;
        o.tapeRecordLength = 333;
    });
    add("leading_garbage", [](dlis::WriteOptions& o) { o.leadingGarbage = std::string(41, 'x'); });
    add("wide_uvari", [](dlis::WriteOptions& o) { o.wideUvari = true; });
    add("everything", [](dlis::WriteOptions& o) {
        o.padAlways = o.checksums = o.trailingLength = o.wideUvari = true;
        o.segmentBody = 29;
        o.visibleRecordLength = 200;
        o.leadingGarbage = std::string(9, 'z');
    });
    for (const Variant& v : variants) {
        const std::string path = write("dlis_layout_" + v.name + ".dlis", files, v.options);
        try {
            const LoadedLog log = loadCaliperLog(path, ReadOptions{});
            expectSameTable(log.table, plain.table, v.name);
            // Bytes before the label may be warned about, naming where the label was found.
            const std::size_t garbage = v.options.leadingGarbage.empty() ? 0 : 1;
            EXPECT_LE(log.info.diagnostics.warningCount,
                      plain.info.diagnostics.warningCount + garbage)
                << v.name << warnings(log.info.diagnostics);
        } catch (const std::exception& e) {
            ADD_FAILURE() << v.name << ": " << e.what();
        }
    }
}

TEST(DlisFixtureTest, EncryptedRecordIsSkippedWithAWarning) {
    dlis::SixArmShape shape;
    shape.rows = 100;
    dlis::WriteOptions options;
    options.encryptedRecord = true;
    const std::string path = write("dlis_encrypted.dlis", {dlis::sixArmLog(shape)}, options);
    const LoadedLog log = loadCaliperLog(path, ReadOptions{});
    expectSixArm(log.table, shape);
    EXPECT_GE(log.info.diagnostics.warningCount, 1u);
    EXPECT_TRUE(anyWarning(log.info.diagnostics, "encrypt"));
}

TEST(DlisFixtureTest, IndexKeepsTemplateDefaultsAbsentAttributesAndCounts) {
    dlis::SixArmShape shape;
    shape.rows = 20;
    dlis::WriteOptions options;
    options.encryptedRecord = true;
    options.leadingGarbage = std::string(37, 'g');
    options.tapeImage = true;
    const std::string bytes =
        dlis::writeDlis({dlis::sixArmLog(shape), dlis::padImagerLog({})}, options);
    caliper3d::io::Diagnostics d;
    const auto index = caliper3d::io::dlis::indexDlis(bytes, "index.dlis", &d);
    EXPECT_TRUE(index.tapeImage);
    EXPECT_EQ(index.sulOffset, 12u + 37u);  // in the file: after the first tape mark
    EXPECT_EQ(index.maxRecordLength, 8192u);
    EXPECT_EQ(index.storageSetId, "CALIPER3D TEST STORAGE SET");
    ASSERT_EQ(index.files.size(), 2u);
    const auto& six = index.files[0];
    EXPECT_EQ(six.id, "SIX ARM CALIPER");
    EXPECT_EQ(six.wellName, shape.wellName);
    EXPECT_EQ(six.encryptedRecords, 1u);
    EXPECT_EQ(six.frameRecords, shape.rows);
    ASSERT_EQ(six.frames.size(), 1u);
    EXPECT_EQ(six.frames[0].indexType, "BOREHOLE-DEPTH");
    EXPECT_EQ(six.frames[0].direction, "INCREASING");
    EXPECT_EQ(six.frames[0].channels.size(), 10u);
    EXPECT_EQ(six.frames[0].frameBytes, 10u * 4u);
    for (const auto& c : six.channels) {
        // RAD1: code and dimension from the template's defaults (the object omits both).
        EXPECT_EQ(c.repCode, caliper3d::io::dlis::kFSINGL) << c.name.id;
        EXPECT_EQ(c.elements(), 1u) << c.name.id;
        EXPECT_EQ(c.name.origin, 41u);
    }
    ASSERT_FALSE(six.parameters.empty());
    EXPECT_EQ(six.parameters[0].name.id, "BS");
    EXPECT_EQ(six.parameters[0].units, "in");
    ASSERT_EQ(six.parameters[0].values.size(), 1u);
    EXPECT_EQ(std::get<double>(six.parameters[0].values[0]), 8.5);
    const auto& pads = index.files[1];
    const auto image = std::find_if(pads.channels.begin(), pads.channels.end(),
                                    [](const auto& c) { return c.name.id == "IMG"; });
    ASSERT_NE(image, pads.channels.end());
    EXPECT_EQ(image->elements(), 8u * 24u);
    EXPECT_EQ(image->repCode, caliper3d::io::dlis::kSNORM);
    EXPECT_TRUE(anyWarning(d, "encrypt"));
}

TEST(DlisFixtureTest, FilesCutShortGiveFewerRowsOrAnErrorNeverACrash) {
    dlis::SixArmShape shape;
    shape.rows = 200;
    for (bool tape : {false, true}) {
        dlis::WriteOptions options;
        options.tapeImage = tape;
        options.visibleRecordLength = 1024;
        const std::string whole = dlis::writeDlis({dlis::sixArmLog(shape)}, options);
        const LoadedLog full = loadCaliperLog(writeBytes("dlis_whole.dlis", whole), ReadOptions{});
        ASSERT_EQ(full.table.rowCount(), shape.rows);
        // The bytes that hold records: a tape image ends in two 12-byte file marks.
        const std::size_t n = whole.size() - (tape ? 24 : 0);
        for (std::size_t cut :
             {std::size_t{3}, std::size_t{40}, std::size_t{79}, std::size_t{81}, std::size_t{86},
              std::size_t{150}, std::size_t{400}, n / 3, n / 2, n / 2 + 1, n - 13, n - 5, n - 1}) {
            const std::string path = writeBytes("dlis_cut.dlis", whole.substr(0, cut));
            const std::string what =
                (tape ? "tape image cut at " : "cut at ") + std::to_string(cut);
            try {
                const LoadedLog log = loadCaliperLog(path, ReadOptions{});
                EXPECT_LT(log.table.rowCount(), shape.rows) << what;
                EXPECT_GE(log.info.diagnostics.warningCount, 1u) << what;
                EXPECT_NE(warnings(log.info.diagnostics).find("byte"), std::string::npos)
                    << what << warnings(log.info.diagnostics);
                // The rows kept are the first ones, whole.
                for (std::size_t i = 0; i < log.table.rowCount(); ++i)
                    ASSERT_EQ(log.table.depth_m[i], full.table.depth_m[i]) << what;
            } catch (const ParseError& e) {
                EXPECT_NE(std::string(e.what()).find(path), std::string::npos)
                    << what << ": " << e.what();
            }
            try {
                (void)describeLog(path, ReadOptions{});
            } catch (const ParseError& e) {
                EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
            }
        }
    }
}

TEST(DlisFixtureTest, RedundantSetAndASecondFrameDoNotChangeTheCaliper) {
    dlis::SixArmShape shape;
    shape.rows = 80;
    dlis::LogicalFileSpec f = dlis::sixArmLog(shape);
    // A gamma-ray frame before the caliper's: the caliper frame is the one read.
    dlis::FrameSpec gamma;
    gamma.name = "GR";
    gamma.channels.push_back({"DEPT", "m", "Depth", dlis::FDOUBL, {1}});
    gamma.channels.push_back({"GR", "gAPI", "Gamma ray", dlis::FSINGL, {1}});
    for (int row = 0; row < 30; ++row) gamma.addRow({990.0 + row, 50.0 + row});
    f.frames.insert(f.frames.begin(), gamma);
    std::vector<dlis::Record> records = dlis::logicalFileRecords(f, {});
    // A redundant copy (RDSET) of the CHANNEL set right after it.
    const auto channels = std::find_if(records.begin(), records.end(), [](const dlis::Record& r) {
        return r.explicitFormat && r.type == 3;
    });
    ASSERT_NE(channels, records.end());
    dlis::Record copy = *channels;
    copy.body[0] = static_cast<char>((copy.body[0] & 0x1F) | 0xA0);
    records.insert(channels + 1, copy);
    const std::string path = writeBytes("dlis_redundant.dlis", dlis::writeStorageUnit(records, {}));
    const LoadedLog log = loadCaliperLog(path, ReadOptions{});
    expectSixArm(log.table, shape);
    caliper3d::io::Diagnostics d;
    const auto index = indexFile(path, d);
    ASSERT_EQ(index.files.size(), 1u);
    EXPECT_EQ(index.files[0].frames.size(), 2u);
}

// ---- What the reader does not do yet: enable each test once it does. ----

// The well name of ORIGIN reaches LogInfo::wellName but not SectionTable::wellName (the LAS
// reader sets both from ~Well WELL).
TEST(DlisFixtureTest, TableCarriesTheOriginsWellName) {
    dlis::SixArmShape shape;
    shape.rows = 20;
    const std::string path = write("dlis_well_name.dlis", {dlis::sixArmLog(shape)});
    const LoadedLog log = loadCaliperLog(path, ReadOptions{});
    EXPECT_EQ(log.info.wellName, shape.wellName);
    EXPECT_EQ(log.table.wellName, shape.wellName);
}

// PARAMETER MDEC (deg) is the magnetic declination, as a LAS ~Parameter MDEC is.
TEST(DlisFixtureTest, MdecParameterIsTheDeclination) {
    dlis::SixArmShape shape;
    shape.rows = 20;
    dlis::WellParameters p;
    const std::string path = write("dlis_mdec.dlis", {dlis::sixArmLogWithParameters(shape, p)});
    const LogInfo info = describeLog(path, ReadOptions{});
    EXPECT_NEAR(info.north.declination.deg, p.declination_deg, 1e-9);
}

// Nine NUL bytes before the label: bytes 0-11 (nine NULs, then "   " of the label's "   1")
// pass for a tape mark (type 0, previous 0, next 0x20202000), so the label at byte 9 is
// missed; the table is read from the first visible record, with three warnings that are not
// so (a tape record past the end, no label, 77 bytes before the first visible record).
TEST(DlisFixtureTest, LeadingNulBytesAreGarbageNotATapeMark) {
    dlis::SixArmShape shape;
    shape.rows = 50;
    dlis::WriteOptions options;
    options.leadingGarbage = std::string(9, '\0');
    const std::string path = write("dlis_nul_garbage.dlis", {dlis::sixArmLog(shape)}, options);
    const LoadedLog log = loadCaliperLog(path, ReadOptions{});
    expectSixArm(log.table, shape);
    EXPECT_EQ(log.info.diagnostics.warningCount, 1u) << warnings(log.info.diagnostics);
    EXPECT_FALSE(anyWarning(log.info.diagnostics, "tape")) << warnings(log.info.diagnostics);
}

// A redundant set (RDSET) is a copy of an earlier set: its objects are not new ones.
TEST(DlisFixtureTest, RedundantSetAddsNoChannels) {
    dlis::SixArmShape shape;
    shape.rows = 20;
    std::vector<dlis::Record> records = dlis::logicalFileRecords(dlis::sixArmLog(shape), {});
    const auto channels = std::find_if(records.begin(), records.end(), [](const dlis::Record& r) {
        return r.explicitFormat && r.type == 3;
    });
    ASSERT_NE(channels, records.end());
    dlis::Record copy = *channels;
    copy.body[0] = static_cast<char>((copy.body[0] & 0x1F) | 0xA0);
    records.insert(channels + 1, copy);
    caliper3d::io::Diagnostics d;
    const auto index =
        caliper3d::io::dlis::indexDlis(dlis::writeStorageUnit(records, {}), "redundant.dlis", &d);
    ASSERT_EQ(index.files.size(), 1u);
    EXPECT_EQ(index.files[0].channels.size(), 10u);
}

// A CHANNEL set giving representation codes RP66 does not define (one far outside an int,
// as a damaged file can): those channels are listed with no code and a warning each, and
// the caliper is read as before.
TEST(DlisFixtureTest, UndefinedRepresentationCodesAreWarnedAndTheCaliperStillReads) {
    dlis::SixArmShape shape;
    shape.rows = 20;
    dlis::LogicalFileSpec f = dlis::sixArmLog(shape);
    dlis::Set odd;
    odd.type = "CHANNEL";
    odd.name = "ODD";
    odd.templ = {dlis::attr("REPRESENTATION-CODE", dlis::numbers(dlis::FDOUBL, {dlis::FSINGL}))};
    for (const auto& [id, code] :
         {std::pair<const char*, double>{"HUGE", 5.0457e231}, {"BYTE", 300.0}, {"HALF", 2.5}}) {
        dlis::Object o;
        o.name = {f.origin, 0, id};
        o.attrs.push_back(dlis::valueOnly(dlis::numbers(dlis::FDOUBL, {code})));
        odd.objects.push_back(o);
    }
    f.extraRecords.push_back({true, 3, dlis::encodeSet(odd), false});
    const std::string path = write("dlis_odd_codes.dlis", {f});
    caliper3d::io::Diagnostics d;
    const auto index = indexFile(path, d);
    ASSERT_EQ(index.files.size(), 1u);
    std::size_t odds = 0;
    for (const auto& ch : index.files[0].channels)
        if (ch.name.id == "HUGE" || ch.name.id == "BYTE" || ch.name.id == "HALF") {
            ++odds;
            EXPECT_EQ(ch.repCode, 0) << ch.name.id;
            EXPECT_TRUE(anyWarning(d, "channel " + lower(ch.name.id) + " gives representation"))
                << warnings(d);
        }
    EXPECT_EQ(odds, 3u);
    EXPECT_EQ(d.warningCount, 3u) << warnings(d);
    expectSixArm(loadCaliperLog(path, ReadOptions{}).table, shape);
}

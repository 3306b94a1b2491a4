// A peer's DLIS corpus (dlisio's test files, ../shared/data/dlis): every file is indexed or
// refused naming itself, every frame of what is indexed is decoded without a crash, and the
// values dlisio's own tests state (python/tests/dlis/*.py of equinor/dlisio, named at each
// check) are read so. The .dlis.part fragments are put together here the way those tests do:
// one visible record after the storage unit label, the lengths of the record and segments
// written to match. The real file 206_05a-_3_DWL_DWL_WIRE_258276498.DLIS is checked against
// the figures dlisio's tests gave for it and against the LAS export of its frames that
// TotalDepth publishes (example_data/LAS of paulross/TotalDepth).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/diagnostics.h"
#include "io/dlis/dlis_objects.h"
#include "io/dlis/dlis_reader.h"
#include "io/parse_error.h"
#include "test_support.h"

using namespace caliper3d::io;
using namespace caliper3d::io::dlis;

namespace {

std::filesystem::path corpus() {
    return caliper3d::test::sharedData() / "dlis";
}

std::string corpusPath(const std::string& rel) {
    return (corpus() / rel).string();
}

std::string fileBytes(const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) throw std::runtime_error("cannot open " + path);
    std::string bytes;
    char buffer[65536];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) bytes.append(buffer, n);
    std::fclose(f);
    return bytes;
}

// Trailing blanks are padding in the fixed-width texts of a file header and a label.
std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == ' ' || s.back() == '\0')) s.pop_back();
    std::size_t start = 0;
    while (start < s.size() && s[start] == ' ') ++start;
    return s.substr(start);
}

void putLength(std::string& bytes, std::size_t at, std::size_t length) {
    bytes[at] = static_cast<char>((length >> 8) & 0xff);
    bytes[at + 1] = static_cast<char>(length & 0xff);
}

// Makes the logical record segment that starts at `at` and runs to the end of `bytes` whole:
// at least 20 bytes and an even length, with pad bytes (the last one their count) where its
// header does not already say it is padded; then writes its length into its header.
void closeSegment(std::string& bytes, std::size_t at) {
    const std::size_t length = bytes.size() - at;
    std::size_t pad = length < 20 ? 20 - length : 0;
    const auto attributes = static_cast<unsigned char>(bytes[at + 2]);
    if (attributes % 2 == 0) {
        if ((bytes.size() + pad) % 2 != 0) ++pad;
        if (pad > 0) {
            bytes[at + 2] = static_cast<char>(attributes | 1);
            bytes.append(pad - 1, '\x01');
            bytes.push_back(static_cast<char>(pad));
        }
    }
    putLength(bytes, at, bytes.size() - at);
}

// The storage unit label (80 bytes), then one visible record (its header at byte 80) holding
// one logical record of one segment (its header at byte 84): the chap3 fragments, the first
// of which carries the label and both headers.
std::string oneRecordFile(const std::vector<std::string>& parts) {
    std::string bytes;
    for (const std::string& p : parts) bytes += fileBytes(corpusPath(p));
    closeSegment(bytes, 84);
    putLength(bytes, 80, bytes.size() - 80);
    return bytes;
}

// The label and a visible record header (the first part), then one logical record of one
// segment per further part: the chap4-7 fragments.
std::string manyRecordFile(const std::vector<std::string>& parts) {
    std::string bytes = fileBytes(corpusPath(parts.at(0)));
    for (std::size_t i = 1; i < parts.size(); ++i) {
        std::string segment = fileBytes(corpusPath(parts[i]));
        closeSegment(segment, 0);
        bytes += segment;
    }
    putLength(bytes, 80, bytes.size() - 80);
    return bytes;
}

// What indexing one file gave: the index, or the refusal's message.
struct Outcome {
    bool refused = false;
    std::string message;
    DlisIndex index;
    Diagnostics diagnostics;
};

Outcome indexBytes(const std::string& bytes, const std::string& name) {
    Outcome out;
    try {
        out.index = indexDlis(bytes, name, &out.diagnostics);
    } catch (const ParseError& e) {
        out.refused = true;
        out.message = e.what();
        EXPECT_EQ(std::string(e.what()).rfind(name, 0), 0u) << e.what();
        EXPECT_FALSE(e.message().empty()) << name;
    }
    return out;
}

Outcome indexFile(const std::string& rel) {
    return indexBytes(fileBytes(corpusPath(rel)), rel);
}

// One decoded frame.
struct FrameRow {
    std::uint32_t number = 0;
    std::vector<double> values;
};

// Every frame of frame `frame` of logical file `file`, all its channels wanted.
std::vector<FrameRow> readAll(const std::string& bytes, const std::string& name,
                              const DlisIndex& index, std::size_t file, std::size_t frame,
                              Diagnostics* diagnostics) {
    const LogicalFile& lf = index.files.at(file);
    const Frame& fr = lf.frames.at(frame);
    std::vector<std::size_t> all(fr.channels.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    const FrameRead wanted = frameRead(lf, fr, all);
    std::vector<FrameRow> rows;
    readFrames(
        bytes, name, index, file, frame, wanted,
        [&](std::uint32_t number, const double* values, std::size_t) {
            rows.push_back({number, std::vector<double>(values, values + wanted.width)});
            return true;
        },
        diagnostics);
    return rows;
}

std::size_t frameIndex(const LogicalFile& lf, const std::string& id) {
    for (std::size_t i = 0; i < lf.frames.size(); ++i)
        if (lf.frames[i].name.id == id) return i;
    ADD_FAILURE() << "no frame " << id;
    return lf.frames.size();
}

const Object* object(const LogicalFile& lf, const std::string& type, const std::string& id) {
    for (const Object* o : lf.objects(type))
        if (o->name.id == id) return o;
    return nullptr;
}

const Object* object(const DlisIndex& index, const std::string& type, const std::string& id) {
    for (const LogicalFile& lf : index.files)
        if (const Object* o = object(lf, type, id)) return o;
    return nullptr;
}

// A value's numbers: one for a plain number, the components of a compound one.
std::vector<double> numbers(const Value& v) {
    if (const double* d = std::get_if<double>(&v)) return {*d};
    if (const auto* c = std::get_if<std::vector<double>>(&v)) return *c;
    return {};
}

bool hasWarning(const Diagnostics& d) {
    return d.warningCount > 0;
}

// The warnings, one a line, for a failure's message.
std::string warningsText(const Diagnostics& d) {
    std::string text;
    for (const Warning& w : d.warnings) text += "\n  warning: " + w.message;
    return text;
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();

// The set types dlisio has a class for (python/dlisio/dlis/file.py, `types`); others are its
// "unknowns".
const std::set<std::string>& dlisioKnownTypes() {
    static const std::set<std::string> types = {"AXIS",
                                                "FILE-HEADER",
                                                "ORIGIN",
                                                "LONG-NAME",
                                                "FRAME",
                                                "CHANNEL",
                                                "ZONE",
                                                "TOOL",
                                                "PARAMETER",
                                                "EQUIPMENT",
                                                "CALIBRATION-MEASUREMENT",
                                                "CALIBRATION-COEFFICIENT",
                                                "CALIBRATION",
                                                "COMPUTATION",
                                                "SPLICE",
                                                "WELL-REFERENCE",
                                                "GROUP",
                                                "PROCESS",
                                                "PATH",
                                                "MESSAGE",
                                                "COMMENT",
                                                "NO-FORMAT"};
    return types;
}

const char* const kRealFile = "206_05a-_3_DWL_DWL_WIRE_258276498.DLIS";

}  // namespace

// ---------------------------------------------------------------------------------------------
// 1. The whole corpus: indexed or refused naming the file, every frame decoded, never a crash.

TEST(DlisCorpusTest, EveryFileIsIndexedOrRefusedNamingTheFile) {
    CALIPER3D_REQUIRE_DATA(corpus());
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(corpus())) {
        if (!entry.is_regular_file()) continue;
        std::string ext = entry.path().extension().string();
        for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (ext != ".dlis" && entry.path().filename() != "nondlis.txt") continue;
        files.push_back(std::filesystem::relative(entry.path(), corpus()).string());
    }
    std::sort(files.begin(), files.end());
    std::size_t indexed = 0, warned = 0, refused = 0, logicalFiles = 0, frames = 0, rows = 0;
    std::size_t frameWarnings = 0;
    std::vector<std::string> refusals;
    for (const std::string& rel : files) {
        SCOPED_TRACE(rel);
        const std::string bytes = fileBytes(corpusPath(rel));
        Outcome out;
        try {
            out = indexBytes(bytes, rel);
        } catch (const std::exception& e) {
            ADD_FAILURE() << "not a ParseError: " << e.what();
            continue;
        }
        if (out.refused) {
            ++refused;
            refusals.push_back(out.message);
            continue;
        }
        ++indexed;
        if (hasWarning(out.diagnostics)) ++warned;
        for (const Warning& w : out.diagnostics.warnings) EXPECT_EQ(w.file, rel);
        logicalFiles += out.index.files.size();
        for (std::size_t f = 0; f < out.index.files.size(); ++f) {
            for (std::size_t k = 0; k < out.index.files[f].frames.size(); ++k) {
                Diagnostics d;
                try {
                    rows += readAll(bytes, rel, out.index, f, k, &d).size();
                } catch (const ParseError& e) {
                    EXPECT_EQ(std::string(e.what()).rfind(rel, 0), 0u) << e.what();
                } catch (const std::exception& e) {
                    ADD_FAILURE() << "frame read threw a non-ParseError: " << e.what();
                }
                ++frames;
                if (hasWarning(d)) ++frameWarnings;
            }
        }
    }
    std::cout << "[ dlis corpus ] " << files.size() << " files: " << indexed << " indexed ("
              << warned << " with warnings), " << refused << " refused; " << logicalFiles
              << " logical files, " << frames << " frames read (" << frameWarnings
              << " with warnings), " << rows << " frame rows\n";
    for (const std::string& r : refusals) std::cout << "[ dlis refused ] " << r << "\n";
    // 157 synthetic .dlis files at dlisio 59b6050, the real file and nondlis.txt.
    EXPECT_EQ(files.size(), 159u);
    EXPECT_EQ(indexed + refused, files.size());
    EXPECT_GT(indexed, files.size() * 3 / 4) << indexed << " of " << files.size();
}

// Files dlisio refuses to load (python/tests/dlis/test_physical_layout.py, test_tif.py,
// test_logical_record.py::test_findfdata_bad_obname, test_loading.py): refused, or read only up
// to the damage with a warning. The ones that are not DLIS at all are refused.
TEST(DlisCorpusTest, FilesDlisioRefusesAreRefusedOrWarned) {
    CALIPER3D_REQUIRE_DATA(corpus());
    for (const char* rel : {"chap2/nondlis.txt", "chap2/old-vr.dlis"}) {
        SCOPED_TRACE(rel);
        EXPECT_TRUE(indexFile(rel).refused);
    }
    for (const char* rel : {
             "chap2/wrong-lrhs.dlis",
             "chap2/lf-lrs-inconsistency.dlis",
             "chap2/padbytes-bad.dlis",
             "chap2/incomplete-vr.dlis",
             "chap2/truncated-in-iflr.dlis",
             "chap2/truncated-in-second-lr.dlis",
             "chap2/truncated-in-lrsh.dlis",
             "chap2/truncated-in-lrsh-vr-over.dlis",
             "chap2/truncated-after-lrsh.dlis",
             "chap2/truncated-lr-no-lrs-in-vr.dlis",
             "chap2/truncated-lr-no-lrs-vr-over.dlis",
             "chap2/truncated-on-full-lr.dlis",
             "chap2/zeroed-in-1st-lr.dlis",
             "chap2/zeroed-in-2nd-lr.dlis",
             "chap3/implicit/fdata-broken-obname.dlis",
             "tif/layout/truncated-in-data.dlis",
             "tif/layout/truncated-in-header.dlis",
             "tif/layout/truncated-after-header.dlis",
             "chap4-7/many-logical-files-error-in-last.dlis",
         }) {
        SCOPED_TRACE(rel);
        const Outcome out = indexFile(rel);
        EXPECT_TRUE(out.refused || hasWarning(out.diagnostics))
            << "read without a word: " << out.index.files.size() << " logical files";
    }
    // test_truncated_in_sul: 32 bytes of a label; dlisio finds no logical file.
    const Outcome sul = indexFile("chap2/truncated-in-sul.dlis");
    EXPECT_TRUE(sul.refused || (sul.index.files.empty() && hasWarning(sul.diagnostics)));
}

// test_error_handler.py: what dlisio salvages when told to go on past the damage; where the
// index is not refused it holds the same.
TEST(DlisCorpusTest, DamagedFilesKeepWhatPrecedesTheDamage) {
    CALIPER3D_REQUIRE_DATA(corpus());
    auto channels = [](const Outcome& out) {
        std::size_t n = 0;
        for (const LogicalFile& lf : out.index.files) n += lf.channels.size();
        return n;
    };
    {
        const Outcome out = indexFile("chap2/truncated-in-second-lr.dlis");
        if (!out.refused) {  // test_truncated_in_data
            EXPECT_EQ(channels(out), 1u);
        }
    }
    {
        const Outcome out = indexFile("chap2/truncated-in-lrsh.dlis");
        if (!out.refused) {  // test_truncated_in_lrsh
            EXPECT_EQ(channels(out), 1u);
        }
    }
    {
        const Outcome out = indexFile("chap2/zeroed-in-2nd-lr.dlis");
        if (!out.refused) {  // test_zeroed_before_vr
            EXPECT_EQ(channels(out), 1u);
        }
    }
    {
        const Outcome out = indexFile("chap2/lf-truncated-after-lrsh.dlis");
        ASSERT_FALSE(out.refused) << out.message;  // the first logical file is whole
        EXPECT_GE(out.index.files.size(), 1u);     // test_truncated_after_lrsh_new_lf: 2
        EXPECT_TRUE(hasWarning(out.diagnostics));
    }
    {
        const Outcome out = indexFile("chap2/padbytes-bad.dlis");
        if (!out.refused) {
            EXPECT_NE(object(out.index, "VALID-SET", "VALID-OBJ"), nullptr);
        }
    }
    {
        // test_parse_objects_unexpected_attribute_in_set: the sets either side of the broken
        // one are read.
        const Outcome out = indexFile("chap3/explicit/broken-in-set.dlis");
        if (!out.refused) {
            EXPECT_NE(object(out.index, "VALID-SET", "VALID-OBJ"), nullptr);
            EXPECT_NE(object(out.index, "GOOOD-SET", "VALID-OBJ"), nullptr);
            EXPECT_TRUE(hasWarning(out.diagnostics));
        }
    }
    {
        // test_tif_padding: zeros after the closing tape marks; both logical files are read.
        const Outcome out = indexFile("tif/irregular/padding.dlis");
        if (!out.refused) {
            EXPECT_EQ(out.index.files.size(), 2u);
            EXPECT_TRUE(out.index.tapeImage);
        }
    }
}

// test_physical_layout.py: the files dlisio loads.
TEST(DlisCorpusTest, FilesDlisioReadsAreRead) {
    CALIPER3D_REQUIRE_DATA(corpus());
    for (const char* rel : {
             "chap2/small.dlis",
             "chap2/7K-file.dlis",
             "chap2/ends-on-FF-01.dlis",
             "chap2/3lrs-in-vr.dlis",
             "chap2/2lr-in-vr.dlis",
             "chap2/1lr-in-2vrs.dlis",
             "chap2/padbytes-encrypted.dlis",
             "chap2/padbytes-large-as-seg-explict.dlis",
             "chap2/padbytes-large-as-seg-implicit.dlis",
             "chap2/3lr-in-vr-one-encrypted.dlis",
             "chap2/too-small-record.dlis",
             "chap2/pre-sul-garbage.dlis",
             "chap2/pre-sul-pre-vrl-garbage.dlis",
             "chap2/missing-sul.dlis",
             "chap2/incomplete-sul.dlis",
             "chap4-7/many-logical-files.dlis",
             "chap4-7/many-logical-files-same-object.dlis",
             "chap4-7/many-logical-files-unnamed-fileheader.dlis",
             "chap4-7/invalid-date-in-origin.dlis",
             "chap4-7/encoded-obname.dlis",
         }) {
        SCOPED_TRACE(rel);
        const Outcome out = indexFile(rel);
        EXPECT_FALSE(out.refused) << out.message;
    }
}

// test_sul: the default label of the small files; test_load_pre_sul_garbage: the label 12
// bytes in; test_load_missing_sul: no label at all.
TEST(DlisCorpusTest, StorageUnitLabel) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const Outcome small = indexFile("chap2/small.dlis");
    ASSERT_FALSE(small.refused) << small.message;
    EXPECT_TRUE(small.index.hasSul);
    EXPECT_EQ(small.index.sulOffset, 0u);
    EXPECT_EQ(small.index.version, "V1.00");
    EXPECT_EQ(small.index.structure, "RECORD");
    EXPECT_EQ(small.index.maxRecordLength, 8192u);
    EXPECT_EQ(trimmed(small.index.storageSetId), "Default Storage Set");
    EXPECT_FALSE(small.index.tapeImage);

    const Outcome garbage = indexFile("chap2/pre-sul-garbage.dlis");
    ASSERT_FALSE(garbage.refused) << garbage.message;
    EXPECT_TRUE(garbage.index.hasSul);
    EXPECT_EQ(garbage.index.sulOffset, 12u);
    EXPECT_EQ(garbage.index.maxRecordLength, 8192u);
    EXPECT_EQ(trimmed(garbage.index.storageSetId), "Default Storage Set");

    const Outcome preVr = indexFile("chap2/pre-sul-pre-vrl-garbage.dlis");
    ASSERT_FALSE(preVr.refused) << preVr.message;
    EXPECT_TRUE(preVr.index.hasSul);
    EXPECT_EQ(preVr.index.sulOffset, 12u);
    EXPECT_EQ(preVr.index.maxRecordLength, 8192u);

    const Outcome missing = indexFile("chap2/missing-sul.dlis");
    ASSERT_FALSE(missing.refused) << missing.message;
    EXPECT_FALSE(missing.index.hasSul);
    EXPECT_FALSE(missing.index.files.empty());

    // test_broken_sul: an incomplete label; the object after it is read.
    const Outcome broken = indexFile("chap2/incomplete-sul.dlis");
    ASSERT_FALSE(broken.refused) << broken.message;
    const Object* o = object(broken.index, "RANDOM_SET3", "RANDOM_OBJECT3");
    ASSERT_NE(o, nullptr);
    ASSERT_NE(o->attribute("RANDOM_ATTRIBUTE3"), nullptr);
    EXPECT_EQ(o->attribute("RANDOM_ATTRIBUTE3")->number(), 3.0);
}

// test_too_small_record: a visible record under 20 bytes; VALID-OBJ's PARAM is "PARAM-VALUE".
TEST(DlisCorpusTest, TooSmallVisibleRecord) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const Outcome out = indexFile("chap2/too-small-record.dlis");
    ASSERT_FALSE(out.refused) << out.message;
    const Object* o = object(out.index, "VALID-SET", "VALID-OBJ");
    ASSERT_NE(o, nullptr);
    ASSERT_NE(o->attribute("PARAM"), nullptr);
    EXPECT_EQ(o->attribute("PARAM")->text(), "PARAM-VALUE");
}

// test_padbytes_as_large_as_*: records all padding hold no object and no frame data.
TEST(DlisCorpusTest, RecordsThatAreAllPadding) {
    CALIPER3D_REQUIRE_DATA(corpus());
    for (const char* rel :
         {"chap2/padbytes-large-as-record.dlis", "chap2/padbytes-large-as-seg-explict.dlis",
          "chap2/padbytes-large-as-seg-implicit.dlis"}) {
        SCOPED_TRACE(rel);
        const Outcome out = indexFile(rel);
        // The first file's only record is padding from end to end (its pad count covers the
        // segment header too): nothing is left to read, and a refusal says so.
        if (std::string(rel) == "chap2/padbytes-large-as-record.dlis" && out.refused) continue;
        ASSERT_FALSE(out.refused) << out.message;
        for (const LogicalFile& lf : out.index.files) {
            for (const Set& s : lf.sets) EXPECT_TRUE(s.objects.empty()) << s.type;
            EXPECT_EQ(lf.frameRecords + lf.unknownFrameRecords, 0u);
        }
    }
}

// test_tif.py: the tape-image files, two logical files each (one for the layout files).
TEST(DlisCorpusTest, TapeImageFiles) {
    CALIPER3D_REQUIRE_DATA(corpus());
    for (const char* rel : {"tif/templates/1.dlis", "tif/templates/2.dlis", "tif/templates/3.dlis",
                            "tif/templates/4.dlis", "tif/templates/5.dlis", "tif/templates/6.dlis",
                            "tif/templates/7.dlis", "tif/templates/8.dlis", "tif/templates/9.dlis",
                            "tif/templates/inconsistency.dlis"}) {
        SCOPED_TRACE(rel);
        const Outcome out = indexFile(rel);
        ASSERT_FALSE(out.refused) << out.message;
        EXPECT_TRUE(out.index.tapeImage);
        EXPECT_EQ(out.index.files.size(), 2u);
    }
    for (const char* rel : {"tif/layout/LR-aligned.dlis", "tif/layout/LR-disaligned.dlis",
                            "tif/layout/TM-contains-FF-01.dlis"}) {
        SCOPED_TRACE(rel);
        const Outcome out = indexFile(rel);
        ASSERT_FALSE(out.refused) << out.message;
        EXPECT_TRUE(out.index.tapeImage);
        EXPECT_EQ(out.index.files.size(), 1u);
    }
    {
        const Outcome out = indexFile("tif/layout/ends-on-FF-01.dlis");
        EXPECT_FALSE(out.refused) << out.message;
    }
    // test_layout_fdata_(dis)aligned: FRAME-REPRCODE (10, 0) has one curve with frames.
    for (const char* rel : {"tif/layout/fdata-aligned.dlis", "tif/layout/fdata-disaligned.dlis"}) {
        SCOPED_TRACE(rel);
        const std::string bytes = fileBytes(corpusPath(rel));
        const Outcome out = indexBytes(bytes, rel);
        ASSERT_FALSE(out.refused) << out.message;
        EXPECT_TRUE(out.index.tapeImage);
        ASSERT_FALSE(out.index.files.empty());
        const LogicalFile& lf = out.index.files[0];
        const std::size_t k = frameIndex(lf, "FRAME-REPRCODE");
        ASSERT_LT(k, lf.frames.size());
        EXPECT_EQ(lf.frames[k].name.origin, 10u);
        EXPECT_EQ(lf.frames[k].channels.size(), 1u);
        Diagnostics d;
        EXPECT_FALSE(readAll(bytes, rel, out.index, 0, k, &d).empty());
    }
}

// test_template_suls_file_TM: after a file tape mark a second storage unit label starts the
// second logical file.
TEST(DlisCorpusTest, TapeImageWithASecondStorageUnitLabel) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const Outcome out = indexFile("tif/irregular/suls-file-TM.dlis");
    ASSERT_FALSE(out.refused) << out.message;
    EXPECT_TRUE(out.index.tapeImage);
    EXPECT_EQ(out.index.files.size(), 2u);
}

// test_findfdata_*: frame data records found whole across visible record borders, by name.
TEST(DlisCorpusTest, FrameDataRecordsAcrossVisibleRecords) {
    CALIPER3D_REQUIRE_DATA(corpus());
    auto fdata = [](const Outcome& out) {
        std::size_t n = 0;
        for (const LogicalFile& lf : out.index.files) {
            std::size_t named = 0;
            for (const Frame& f : lf.frames) named += f.records;
            n += named + lf.unknownFrameRecords;
        }
        return n;
    };
    const std::map<std::string, std::size_t> expected = {
        {"chap3/implicit/fdata-vr-aligned.dlis", 1},
        {"chap3/implicit/fdata-vr-aligned-padding.dlis", 1},
        {"chap3/implicit/fdata-many-in-same-vr.dlis", 4},
        {"chap3/implicit/fdata-non-0-non-1-type.dlis", 0},
        {"chap3/implicit/fdata-vr-disaligned.dlis", 1},
        {"chap3/implicit/fdata-vr-disaligned-checksum.dlis", 1},
        {"chap3/implicit/fdata-vr-disaligned-in-obname.dlis", 1},
        {"chap3/implicit/fdata-vr-obname-trailing.dlis", 1},
        {"chap3/implicit/fdata-encrypted.dlis", 0},
    };
    for (const auto& [rel, count] : expected) {
        SCOPED_TRACE(rel);
        const Outcome out = indexFile(rel);
        ASSERT_FALSE(out.refused) << out.message;
        EXPECT_EQ(fdata(out), count);
    }
    const Outcome enc = indexFile("chap3/implicit/fdata-encrypted.dlis");
    ASSERT_FALSE(enc.refused);
    std::size_t encrypted = 0;
    for (const LogicalFile& lf : enc.index.files) encrypted += lf.encryptedRecords;
    EXPECT_GE(encrypted, 1u);
}

// test_partitioning.py: three logical files, the first without a file header.
TEST(DlisCorpusTest, ManyLogicalFiles) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const std::string rel = "chap4-7/many-logical-files.dlis";
    const std::string bytes = fileBytes(corpusPath(rel));
    const Outcome out = indexBytes(bytes, rel);
    ASSERT_FALSE(out.refused) << out.message;
    ASSERT_EQ(out.index.files.size(), 3u);
    const LogicalFile& f1 = out.index.files[0];
    const LogicalFile& f2 = out.index.files[1];
    const LogicalFile& f3 = out.index.files[2];
    // test_objects_ownership
    EXPECT_EQ(f1.objects("FILE-HEADER").size(), 0u);
    EXPECT_EQ(f1.objects("ORIGIN").size(), 2u);
    EXPECT_EQ(f1.channels.size(), 4u);
    EXPECT_EQ(f1.frames.size(), 2u);
    EXPECT_EQ(f1.frameRecords + f1.unknownFrameRecords, 0u);
    EXPECT_EQ(trimmed(f2.id), "Yet another logical file");
    const Object* fh2 = object(f2, "FILE-HEADER", "N");
    ASSERT_NE(fh2, nullptr);
    EXPECT_EQ(fh2->name.origin, 11u);
    EXPECT_EQ(trimmed(fh2->attribute("SEQUENCE-NUMBER")->text()), "10");
    EXPECT_EQ(f2.objects("ORIGIN").size(), 1u);
    EXPECT_EQ(f2.channels.size(), 2u);
    EXPECT_EQ(f2.frames.size(), 3u);
    const std::size_t inc = frameIndex(f2, "FRAME-INC");
    ASSERT_LT(inc, f2.frames.size());
    EXPECT_EQ(f2.frames[inc].records, 2u);  // test_partitioning: fdata_index [824, 1060]
    EXPECT_EQ(trimmed(f3.id), "some logical file");
    EXPECT_EQ(f3.channels.size(), 0u);
    EXPECT_EQ(f3.frameRecords + f3.unknownFrameRecords, 0u);
    for (std::size_t f = 0; f < out.index.files.size(); ++f)
        for (std::size_t k = 0; k < out.index.files[f].frames.size(); ++k) {
            Diagnostics d;
            readAll(bytes, rel, out.index, f, k, &d);
        }
}

// test_objects_with_encrypted_records_ownership: two logical files that each define CHANN1
// (10, 0), three dimensions in the first, one in the second.
TEST(DlisCorpusTest, SameObjectInTwoLogicalFiles) {
    CALIPER3D_REQUIRE_DATA(corpus());
    for (const char* rel : {"chap4-7/many-logical-files-same-object.dlis",
                            "chap4-7/many-logical-files-unnamed-fileheader.dlis"}) {
        SCOPED_TRACE(rel);
        const Outcome out = indexFile(rel);
        ASSERT_FALSE(out.refused) << out.message;
        ASSERT_EQ(out.index.files.size(), 2u);
        const Channel* c1 = out.index.files[0].channel(ObjectName{10, 0, "CHANN1"});
        ASSERT_NE(c1, nullptr);
        EXPECT_EQ(c1->dimension.size(), 3u);
    }
    const Outcome same = indexFile("chap4-7/many-logical-files-same-object.dlis");
    const Channel* c2 = same.index.files.at(1).channel(ObjectName{10, 0, "CHANN1"});
    ASSERT_NE(c2, nullptr);
    EXPECT_EQ(c2->dimension.size(), 1u);
    const Outcome unnamed = indexFile("chap4-7/many-logical-files-unnamed-fileheader.dlis");
    const Channel* inc = unnamed.index.files.at(1).channel(ObjectName{10, 0, "INC-CH1"});
    ASSERT_NE(inc, nullptr);
    EXPECT_EQ(inc->dimension.size(), 1u);
}

// ---------------------------------------------------------------------------------------------
// 2. Logical record syntax (chap3, test_logical_record.py), files put together from fragments.

namespace {

// The one object (1, 1, "OBJECT") of the first set of a chap3 file put together from `parts`.
struct Chap3 {
    Outcome out;
    const Set* set = nullptr;
    const Object* object = nullptr;
};

Chap3 chap3(const std::vector<std::string>& parts, const std::string& objectId = "OBJECT") {
    Chap3 c;
    std::string name = "chap3";
    for (const std::string& p : parts) name += "+" + std::filesystem::path(p).stem().string();
    c.out = indexBytes(oneRecordFile(parts), name);
    if (c.out.refused || c.out.index.files.empty()) return c;
    for (const LogicalFile& lf : c.out.index.files)
        for (const Set& s : lf.sets)
            for (const Object& o : s.objects)
                if (o.name.id == objectId && !c.object) {
                    c.set = &s;
                    c.object = &o;
                }
    return c;
}

}  // namespace

// test_repcode: one attribute of each representation code, its value as dlisio reads it.
TEST(DlisCorpusTest, Chap3EveryRepresentationCodeInAnAttribute) {
    CALIPER3D_REQUIRE_DATA(corpus());
    struct Case {
        const char* part;
        const char* label;
        int code;
        std::vector<double> numbers;  // empty for the texts and names
        const char* text;             // "" for numbers
    };
    const std::vector<Case> cases = {
        {"01-fshort", "FSHORT", kFSHORT, {-1}, ""},
        {"02-fsingl", "FSINGL", kFSINGL, {5.5}, ""},
        {"03-fsing1", "FSING1", kFSING1, {-2, 2}, ""},
        {"04-fsing2", "FSING2", kFSING2, {117, -13.25, 32444}, ""},
        {"05-isingl", "ISINGL", kISINGL, {-12}, ""},
        {"06-vsingl", "VSINGL", kVSINGL, {0.125}, ""},
        {"07-fdoubl", "FDOUBL", kFDOUBL, {900000000000000.5}, ""},
        {"08-fdoub1", "FDOUB1", kFDOUB1, {-13.5, -27670}, ""},
        {"09-fdoub2", "FDOUB2", kFDOUB2, {6728332223, -45.75, -0.0625}, ""},
        {"10-csingl", "CSINGL", kCSINGL, {93, -14}, ""},
        {"11-cdoubl", "CDOUBL", kCDOUBL, {125533556, -4.75}, ""},
        {"12-sshort", "SSHORT", kSSHORT, {89}, ""},
        {"13-snorm", "SNORM", kSNORM, {-153}, ""},
        {"14-slong", "SLONG", kSLONG, {2147483647}, ""},
        {"15-ushort", "USHORT", kUSHORT, {6}, ""},
        {"16-unorm", "UNORM", kUNORM, {32921}, ""},
        {"17-ulong", "ULONG", kULONG, {1}, ""},
        {"18-uvari", "UVARI", kUVARI, {257}, ""},
        {"19-ident", "IDENT", kIDENT, {}, "VALUE"},
        {"20-ascii", "ASCII", kASCII, {}, "ASCII VALUE"},
        {"22-origin", "ORIGIN", kORIGIN, {16777217}, ""},
        {"26-status", "STATUS", kSTATUS, {1}, ""},
        {"27-units", "UNITS", kUNITS, {}, "unit"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.part);
        const Chap3 f =
            chap3({"chap3/start.dlis.part", std::string("chap3/repcode/") + c.part + ".dlis.part",
                   "chap3/object/object.dlis.part"});
        ASSERT_FALSE(f.out.refused) << f.out.message;
        ASSERT_NE(f.object, nullptr) << warningsText(f.out.diagnostics);
        EXPECT_EQ(f.set->type, "VERY_MUCH_TESTY_SET");
        const Attribute* a = f.object->attribute(c.label);
        ASSERT_NE(a, nullptr);
        EXPECT_EQ(a->repCode, c.code);
        EXPECT_EQ(repCodeName(a->repCode), c.label);
        ASSERT_EQ(a->values.size(), 1u);
        if (c.numbers.empty()) {
            EXPECT_EQ(a->text(), c.text);
            EXPECT_TRUE(std::isnan(a->number()));
        } else {
            EXPECT_EQ(numbers(a->values[0]), c.numbers);
            EXPECT_EQ(a->number(), c.numbers[0]);
        }
    }
    {
        // DTIME 1971-03-21 18:04:14.386 (the zone is not in dlisio's check).
        const Chap3 f = chap3({"chap3/start.dlis.part", "chap3/repcode/21-dtime.dlis.part",
                               "chap3/object/object.dlis.part"});
        ASSERT_NE(f.object, nullptr) << warningsText(f.out.diagnostics);
        const Attribute* a = f.object->attribute("DTIME");
        ASSERT_NE(a, nullptr);
        EXPECT_EQ(a->repCode, kDTIME);
        EXPECT_EQ(a->text().substr(0, 23), "1971-03-21 18:04:14.386") << a->text();
    }
    {
        const Chap3 f = chap3({"chap3/start.dlis.part", "chap3/repcode/23-obname.dlis.part",
                               "chap3/object/object.dlis.part"});
        ASSERT_NE(f.object, nullptr) << warningsText(f.out.diagnostics);
        const Attribute* a = f.object->attribute("OBNAME");
        ASSERT_NE(a, nullptr);
        ASSERT_EQ(a->values.size(), 1u);
        const auto* n = std::get_if<ObjectName>(&a->values[0]);
        ASSERT_NE(n, nullptr);
        EXPECT_EQ(*n, (ObjectName{18, 5, "OBNAME_I"}));
        EXPECT_EQ(a->text(), "OBNAME_I");
    }
    {
        const Chap3 f = chap3({"chap3/start.dlis.part", "chap3/repcode/24-objref.dlis.part",
                               "chap3/object/object.dlis.part"});
        ASSERT_NE(f.object, nullptr) << warningsText(f.out.diagnostics);
        const Attribute* a = f.object->attribute("OBJREF");
        ASSERT_NE(a, nullptr);
        ASSERT_EQ(a->values.size(), 1u);
        const auto* r = std::get_if<ObjectRef>(&a->values[0]);
        ASSERT_NE(r, nullptr);
        EXPECT_EQ(r->type, "OBJREF_I");
        EXPECT_EQ(r->name, (ObjectName{25, 3, "OBJREF_OBNAME"}));
    }
    {
        const Chap3 f = chap3({"chap3/start.dlis.part", "chap3/repcode/25-attref.dlis.part",
                               "chap3/object/object.dlis.part"});
        ASSERT_NE(f.object, nullptr) << warningsText(f.out.diagnostics);
        const Attribute* a = f.object->attribute("ATTREF");
        ASSERT_NE(a, nullptr);
        ASSERT_EQ(a->values.size(), 1u);
        const auto* r = std::get_if<AttributeRef>(&a->values[0]);
        ASSERT_NE(r, nullptr);
        EXPECT_EQ(r->type, "FIRST_INDENT");
        EXPECT_EQ(r->name, (ObjectName{3, 2, "ATTREF_OBNAME"}));
        EXPECT_EQ(r->label, "SECOND_INDENT");
    }
}

namespace {

const char* const kStart = "chap3/start.dlis.part";
const char* const kObject = "chap3/object/object.dlis.part";
const char* const kDefault = "chap3/template/default.dlis.part";

// DEFAULT_ATTRIBUTE of the template default.dlis.part: two FDOUBL, -0.75 and 10.0, in
// "default attr units".
void expectTemplateDefault(const Attribute* a) {
    ASSERT_NE(a, nullptr);
    EXPECT_EQ(a->units, "default attr units");
    EXPECT_EQ(a->count, 2u);
    EXPECT_EQ(a->repCode, kFDOUBL);
    ASSERT_EQ(a->values.size(), 2u);
    EXPECT_EQ(a->number(0), -0.75);
    EXPECT_EQ(a->number(1), 10.0);
}

}  // namespace

// test_default_attribute: an empty attribute in the object takes the template's default.
TEST(DlisCorpusTest, Chap3TemplateDefault) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const Chap3 f = chap3({kStart, kDefault, kObject, "chap3/objattr/empty.dlis.part"});
    ASSERT_FALSE(f.out.refused) << f.out.message;
    ASSERT_NE(f.object, nullptr) << warningsText(f.out.diagnostics);
    EXPECT_EQ(f.object->name, (ObjectName{1, 1, "OBJECT"}));
    EXPECT_EQ(f.set->type, "VERY_MUCH_TESTY_SET");
    EXPECT_EQ(f.set->name, "SETNAME");
    ASSERT_EQ(f.set->templ.size(), 1u);
    EXPECT_EQ(f.set->templ[0].label, "DEFAULT_ATTRIBUTE");
    expectTemplateDefault(f.object->attribute("DEFAULT_ATTRIBUTE"));
}

// An object that ends before the template's attributes: every one is the default
// (test_default_attribute_cut).
TEST(DlisCorpusTest, Chap3ObjectWithoutAttributesTakesTheDefaults) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const Chap3 f = chap3({kStart, "chap3/template/invariant.dlis.part", kDefault, kObject});
    ASSERT_FALSE(f.out.refused) << f.out.message;
    ASSERT_NE(f.object, nullptr) << warningsText(f.out.diagnostics);
    EXPECT_NE(f.object->attribute("INVARIANT_ATTRIBUTE"), nullptr);
    expectTemplateDefault(f.object->attribute("DEFAULT_ATTRIBUTE"));
}

// test_objattr_same_as_default_no_value: count, code and units repeated, no value: the
// template's value.
TEST(DlisCorpusTest, Chap3AttributeWithoutValueKeepsTheDefaultValue) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const Chap3 f =
        chap3({kStart, kDefault, kObject, "chap3/objattr/repeat-default-novalue.dlis.part"});
    ASSERT_FALSE(f.out.refused) << f.out.message;
    ASSERT_NE(f.object, nullptr) << warningsText(f.out.diagnostics);
    expectTemplateDefault(f.object->attribute("DEFAULT_ATTRIBUTE"));
}

// test_all_attribute_bits: count 4, USHORT, "overwritten units", 1 2 3 4.
TEST(DlisCorpusTest, Chap3AttributeOverridingEverything) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const Chap3 f = chap3({kStart, kDefault, kObject, "chap3/objattr/all-set.dlis.part"});
    ASSERT_FALSE(f.out.refused) << f.out.message;
    ASSERT_NE(f.object, nullptr) << warningsText(f.out.diagnostics);
    const Attribute* a = f.object->attribute("DEFAULT_ATTRIBUTE");
    ASSERT_NE(a, nullptr);
    EXPECT_EQ(a->units, "overwritten units");
    EXPECT_EQ(a->repCode, kUSHORT);
    EXPECT_EQ(a->count, 4u);
    ASSERT_EQ(a->values.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(a->number(i), double(i + 1));
}

// test_invariant_attribute: three STATUS, false false true, "invariant units".
TEST(DlisCorpusTest, Chap3InvariantAttribute) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const Chap3 f = chap3({kStart, "chap3/template/invariant.dlis.part", kObject});
    ASSERT_FALSE(f.out.refused) << f.out.message;
    ASSERT_NE(f.object, nullptr) << warningsText(f.out.diagnostics);
    ASSERT_FALSE(f.set->templ.empty());
    EXPECT_TRUE(f.set->templ[0].invariant);
    const Attribute* a = f.object->attribute("INVARIANT_ATTRIBUTE");
    ASSERT_NE(a, nullptr);
    EXPECT_EQ(a->units, "invariant units");
    EXPECT_EQ(a->repCode, kSTATUS);
    ASSERT_EQ(a->values.size(), 3u);
    EXPECT_EQ(a->number(0), 0.0);
    EXPECT_EQ(a->number(1), 0.0);
    EXPECT_EQ(a->number(2), 1.0);
}

// test_invariant_attribute_in_object: an object's attribute marked invariant is read (dlisio:
// value 8.0, with a warning).
TEST(DlisCorpusTest, Chap3InvariantFlagInAnObjectIsReadWithAWarning) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const Chap3 f = chap3({kStart, kDefault, kObject, "chap3/objattr/invariant.dlis.part"});
    ASSERT_FALSE(f.out.refused) << f.out.message;
    EXPECT_TRUE(hasWarning(f.out.diagnostics));
    ASSERT_NE(f.object, nullptr) << warningsText(f.out.diagnostics);
    const Attribute* a = f.object->attribute("DEFAULT_ATTRIBUTE");
    ASSERT_NE(a, nullptr);
    ASSERT_EQ(a->values.size(), 1u);
    EXPECT_EQ(a->number(), 8.0);
}

// test_absent_attribute: ABSATR in the object; test_absent_attribute_in_template: ABSATR in
// the template is skipped.
TEST(DlisCorpusTest, Chap3AbsentAttribute) {
    CALIPER3D_REQUIRE_DATA(corpus());
    {
        const Chap3 f = chap3({kStart, "chap3/template/invariant.dlis.part", kDefault, kObject,
                               "chap3/objattr/absent.dlis.part"});
        ASSERT_FALSE(f.out.refused) << f.out.message;
        ASSERT_NE(f.object, nullptr) << warningsText(f.out.diagnostics);
        EXPECT_NE(f.object->attribute("INVARIANT_ATTRIBUTE"), nullptr);
        EXPECT_EQ(f.object->attribute("DEFAULT_ATTRIBUTE"), nullptr);
    }
    {
        const Chap3 f = chap3({kStart, "chap3/template/absent.dlis.part", kDefault, kObject});
        ASSERT_FALSE(f.out.refused) << f.out.message;
        ASSERT_NE(f.object, nullptr) << warningsText(f.out.diagnostics);
        expectTemplateDefault(f.object->attribute("DEFAULT_ATTRIBUTE"));
    }
}

// test_global_default_attribute: a label only; one IDENT without units or value.
TEST(DlisCorpusTest, Chap3GlobalDefault) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const Chap3 f = chap3({kStart, "chap3/template/global-default.dlis.part", kObject,
                           "chap3/objattr/empty.dlis.part"});
    ASSERT_FALSE(f.out.refused) << f.out.message;
    ASSERT_NE(f.object, nullptr) << warningsText(f.out.diagnostics);
    const Attribute* a = f.object->attribute("GLOBAL_DEFAULT_ATTRIBUTE");
    ASSERT_NE(a, nullptr);
    EXPECT_EQ(a->units, "");
    EXPECT_EQ(a->repCode, kIDENT);
    EXPECT_EQ(a->count, 1u);
    EXPECT_EQ(a->text(), "");
}

// test_no_template: an object of a set without template has no attribute.
TEST(DlisCorpusTest, Chap3NoTemplate) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const Chap3 f = chap3({kStart, kObject});
    ASSERT_FALSE(f.out.refused) << f.out.message;
    ASSERT_NE(f.object, nullptr) << warningsText(f.out.diagnostics);
    EXPECT_TRUE(f.object->attributes.empty());
}

// test_count0_novalue, test_count0_value_bit, test_count0_different_repcode: count 0, no
// value; the code given (UNITS) replaces the template's.
TEST(DlisCorpusTest, Chap3CountZero) {
    CALIPER3D_REQUIRE_DATA(corpus());
    for (const char* part :
         {"count0-novalue-bit", "count0-value-bit", "count0-different-repcode"}) {
        SCOPED_TRACE(part);
        const Chap3 f =
            chap3({kStart, kDefault, kObject, std::string("chap3/objattr/") + part + ".dlis.part"});
        ASSERT_FALSE(f.out.refused) << f.out.message;
        ASSERT_NE(f.object, nullptr) << warningsText(f.out.diagnostics);
        const Attribute* a = f.object->attribute("DEFAULT_ATTRIBUTE");
        ASSERT_NE(a, nullptr);
        EXPECT_EQ(a->count, 0u);
        EXPECT_TRUE(a->values.empty());
        if (std::string(part) == "count0-different-repcode") {
            EXPECT_EQ(a->repCode, kUNITS);
        }
    }
}

// test_label_bit_set_in_attribute: a label flag in an object's attribute is read with a
// warning; the value is the template's.
TEST(DlisCorpusTest, Chap3LabelFlagInAnObject) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const Chap3 f = chap3({kStart, kDefault, kObject, "chap3/objattr/label-bit-set.dlis.part"});
    ASSERT_FALSE(f.out.refused) << f.out.message;
    ASSERT_NE(f.object, nullptr) << warningsText(f.out.diagnostics);
    const Attribute* a = f.object->attribute("DEFAULT_ATTRIBUTE");
    ASSERT_NE(a, nullptr);
    EXPECT_FALSE(a->values.empty());
}

// test_novalue_more_count: a count above the template's has no value to take; the next
// object's own value is still read.
TEST(DlisCorpusTest, Chap3CountAboveTheTemplate) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const Chap3 f = chap3({kStart, kDefault, kObject, "chap3/objattr/count9-novalue.dlis.part",
                           "chap3/object/object2.dlis.part", "chap3/objattr/all-set.dlis.part"},
                          "OBJECT2");
    if (f.out.refused) return;  // dlisio refuses the first object's attribute
    ASSERT_NE(f.object, nullptr) << warningsText(f.out.diagnostics);
    const Attribute* a = f.object->attribute("DEFAULT_ATTRIBUTE");
    ASSERT_NE(a, nullptr);
    ASSERT_EQ(a->values.size(), 4u);
    EXPECT_EQ(a->number(3), 4.0);
}

// test_set_redundant, test_set_replacement.
TEST(DlisCorpusTest, Chap3RedundantAndReplacementSets) {
    CALIPER3D_REQUIRE_DATA(corpus());
    {
        const Chap3 f = chap3({"chap3/sul.dlis.part", "chap3/set/redundant.dlis.part", kDefault,
                               kObject, "chap3/objattr/all-set.dlis.part"});
        ASSERT_FALSE(f.out.refused) << f.out.message;
        ASSERT_NE(f.set, nullptr);
        EXPECT_EQ(f.set->type, "REDUNDANT");
        EXPECT_TRUE(f.set->redundant);
        EXPECT_FALSE(f.set->replacement);
    }
    {
        const Chap3 f = chap3({"chap3/sul.dlis.part", "chap3/set/replacement.dlis.part", kDefault,
                               kObject, "chap3/objattr/all-set.dlis.part"});
        ASSERT_FALSE(f.out.refused) << f.out.message;
        ASSERT_NE(f.set, nullptr);
        EXPECT_EQ(f.set->type, "REPLACEMENT");
        EXPECT_TRUE(f.set->replacement);
        EXPECT_FALSE(f.set->redundant);
    }
}

// test_set_type_bit_not_set_in_set: a set whose type flag is not set is read with a warning.
TEST(DlisCorpusTest, Chap3SetWithoutTypeFlagIsReadWithAWarning) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const Chap3 f =
        chap3({"chap3/sul.dlis.part", "chap3/set/no-type-flag.dlis.part", kDefault, kObject});
    ASSERT_FALSE(f.out.refused) << f.out.message;
    EXPECT_TRUE(hasWarning(f.out.diagnostics));
    ASSERT_NE(f.object, nullptr) << warningsText(f.out.diagnostics);
    EXPECT_EQ(f.set->type, "VERY_MUCH_TESTY_SET");
    expectTemplateDefault(f.object->attribute("DEFAULT_ATTRIBUTE"));
}

// test_object_name_bit_not_set_in_object: an object without its name flag is read with a
// warning.
TEST(DlisCorpusTest, Chap3ObjectWithoutNameFlagIsReadWithAWarning) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const Chap3 f = chap3({kStart, kDefault, "chap3/object/no-name-bit.dlis.part"});
    ASSERT_FALSE(f.out.refused) << f.out.message;
    ASSERT_NE(f.object, nullptr) << warningsText(f.out.diagnostics);
    EXPECT_EQ(f.object->name, (ObjectName{1, 1, "OBJECT"}));
    expectTemplateDefault(f.object->attribute("DEFAULT_ATTRIBUTE"));
}

// test_cut_before_object: a set with a template and no object.
TEST(DlisCorpusTest, Chap3SetWithoutObjects) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const Chap3 f = chap3({kStart, kDefault});
    ASSERT_FALSE(f.out.refused) << f.out.message;
    EXPECT_EQ(f.object, nullptr);
}

// The fragments dlisio refuses to make sense of (invalid codes, a set inside an object, records
// cut short, broken UTF-8): refused naming the file, or read with a warning; never a crash.
TEST(DlisCorpusTest, Chap3MalformedRecordsAreRefusedOrWarned) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const std::string start = "chap3/start.dlis.part";
    const std::string obj = "chap3/object/object.dlis.part";
    const std::vector<std::vector<std::string>> cases = {
        {start, "chap3/template/invalid-repcode-value.dlis.part", obj,
         "chap3/objattr/all-set.dlis.part"},
        {start, "chap3/template/default.dlis.part", obj,
         "chap3/objattr/reprcode-invalid-value.dlis.part"},
        {"chap3/sul.dlis.part", "chap3/set/no-set-start.dlis.part",
         "chap3/template/default.dlis.part", obj},
        {start, "chap3/template/default.dlis.part", obj, "chap3/set/second-set.dlis.part",
         "chap3/template/invariant.dlis.part", obj},
        {start, "chap3/template/default.dlis.part", "chap3/set/second-set.dlis.part",
         "chap3/template/invariant.dlis.part", obj},
        {start, "chap3/template/invariant.dlis.part", obj, "chap3/objattr/empty.dlis.part"},
        {start},
        {start, "chap3/template/default.dlis.part", "chap3/object/cut-middle-type.dlis.part"},
        {start, "chap3/template/default.dlis.part", obj,
         "chap3/objattr/cut-middle-value.dlis.part"},
        {start, "chap3/template/cut-after-attribute.dlis.part"},
    };
    for (const auto& parts : cases) {
        SCOPED_TRACE(parts.back());
        const Chap3 f = chap3(parts);
        EXPECT_TRUE(f.out.refused || hasWarning(f.out.diagnostics));
    }
    // Read or refused, never a crash: odd but legal-looking fragments.
    const std::vector<std::vector<std::string>> survivable = {
        {start, "chap3/template/invalid-repcode-no-value.dlis.part", obj},
        {start, "chap3/template/invalid-repcode-no-value.dlis.part",
         "chap3/template/default.dlis.part", obj, "chap3/objattr/all-set.dlis.part"},
        {start, "chap3/template/global-default.dlis.part", obj,
         "chap3/objattr/reprcode-invalid-no-value.dlis.part", "chap3/object/object2.dlis.part",
         "chap3/objattr/all-set.dlis.part"},
        {start, "chap3/template/default.dlis.part", obj, "chap3/objattr/csingle-novalue.dlis.part"},
        {start, "chap3/template/default.dlis.part", obj, "chap3/objattr/count1-novalue.dlis.part"},
        {start, "chap3/template/label-bit-not-set.dlis.part", obj},
        {start, "chap3/repcode/invalid-dtime.dlis.part", obj},
        {start, "chap3/template/default.dlis.part", obj,
         "chap3/objattr/broken-utf8-value.dlis.part"},
        {start, "chap3/template/default.dlis.part", obj,
         "chap3/objattr/broken-utf8-obname-value.dlis.part"},
        {start, "chap3/template/default.dlis.part", "chap3/object/broken-utf8-object.dlis.part"},
        {start, "chap3/template/broken-utf8-label.dlis.part", obj},
        {"chap3/sul.dlis.part", "chap3/set/broken-utf8-set.dlis.part",
         "chap3/template/default.dlis.part", obj},
        {"chap3/sul.dlis.part", "chap3/set/name-bit-set-no-name.dlis.part",
         "chap3/template/default.dlis.part", obj},
        {start, "chap3/template/default.dlis.part", "chap3/object/no-bit-no-name.dlis.part"},
    };
    for (const auto& parts : survivable) {
        SCOPED_TRACE(parts.back());
        chap3(parts);
    }
}

// ---------------------------------------------------------------------------------------------
// Chapters 4-7: objects and frames (test_object_structures.py, test_curves.py,
// test_curves_reprcodes.py, test_logical_file.py).

namespace {

// conftest.py's `fpath`: every kind of object dlisio knows, in one logical file.
std::string semanticFile() {
    std::vector<std::string> parts;
    for (const char* p :
         {"envelope",       "file-header",      "origin",         "well-reference-point",
          "axis",           "long-name-record", "channel",        "frame",
          "fdata-frame1-1", "fdata-frame1-2",   "fdata-frame1-3", "path",
          "zone",           "parameter",        "equipment",      "tool",
          "tool-wrong",     "process",          "computation",    "measurement",
          "coefficient",    "calibration",      "group",          "splice",
          "message",        "comment",          "update",         "no-format",
          "unknown"})
        parts.push_back(std::string("chap4-7/eflr/") + p + ".dlis.part");
    return manyRecordFile(parts);
}

}  // namespace

namespace {

// The file of conftest.py's `fpath`, indexed once.
struct SemanticFile {
    std::string bytes;
    Outcome out;
};

const SemanticFile& semantic() {
    static const SemanticFile file = [] {
        SemanticFile f;
        f.bytes = semanticFile();
        f.out = indexBytes(f.bytes, "semantic.dlis");
        return f;
    }();
    return file;
}

}  // namespace

// test_file_header, test_origin: the file header and the defining origin.
TEST(DlisCorpusTest, Chap4FileHeaderAndOrigin) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const Outcome& out = semantic().out;
    ASSERT_FALSE(out.refused) << out.message;
    ASSERT_EQ(out.index.files.size(), 1u);
    const LogicalFile& lf = out.index.files[0];
    EXPECT_EQ(trimmed(lf.id), "some logical file");
    const Object* fh = object(lf, "FILE-HEADER", "N");
    ASSERT_NE(fh, nullptr);
    EXPECT_EQ(fh->name.origin, 10u);
    EXPECT_EQ(trimmed(fh->attribute("SEQUENCE-NUMBER")->text()), "8");
    // test_origin: the defining origin is the first.
    EXPECT_EQ(lf.wellName, "SECRET-WELL");
    EXPECT_EQ(lf.wellId, "CODED-WELL");
    EXPECT_EQ(lf.fieldName, "WILDCAT");
    EXPECT_EQ(lf.company, "The Company");
    EXPECT_EQ(lf.producer, "Test Production");
    EXPECT_EQ(lf.product, "fantasy");
    EXPECT_EQ(lf.creationTime.substr(0, 19), "2019-05-02 13:51:00") << lf.creationTime;
    const Object* origin = object(lf, "ORIGIN", "DEFINING_ORIGIN");
    ASSERT_NE(origin, nullptr);
    EXPECT_EQ(origin->attribute("FILE-SET-NUMBER")->number(), 1042.0);
    EXPECT_EQ(origin->attribute("PRODUCER-CODE")->number(), 307.0);
    EXPECT_EQ(origin->attribute("PROGRAMS")->values.size(), 2u);
    const Object* random = object(lf, "ORIGIN", "RANDOM");
    ASSERT_NE(random, nullptr);
    EXPECT_EQ(random->name.origin, 127u);
}

// test_dlis_types, test_object_unknown: how many objects of each type.
TEST(DlisCorpusTest, Chap4ObjectsOfEveryKind) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const Outcome& out = semantic().out;
    ASSERT_FALSE(out.refused) << out.message;
    ASSERT_EQ(out.index.files.size(), 1u);
    const LogicalFile& lf = out.index.files[0];
    EXPECT_EQ(lf.objects("ORIGIN").size(), 2u);
    EXPECT_EQ(lf.objects("AXIS").size(), 3u);
    EXPECT_EQ(lf.objects("LONG-NAME").size(), 5u);
    EXPECT_EQ(lf.objects("CHANNEL").size(), 4u);
    EXPECT_EQ(lf.channels.size(), 4u);
    EXPECT_EQ(lf.objects("FRAME").size(), 2u);
    EXPECT_EQ(lf.frames.size(), 2u);
    EXPECT_EQ(lf.objects("ZONE").size(), 1u);
    EXPECT_EQ(lf.objects("TOOL").size(), 2u);
    EXPECT_EQ(lf.objects("PARAMETER").size(), 3u);
    EXPECT_EQ(lf.parameters.size(), 3u);
    EXPECT_EQ(lf.objects("PROCESS").size(), 2u);
    EXPECT_EQ(lf.objects("GROUP").size(), 3u);
    EXPECT_EQ(lf.objects("WELL-REFERENCE").size(), 1u);
    EXPECT_EQ(lf.objects("SPLICE").size(), 1u);
    EXPECT_EQ(lf.objects("PATH").size(), 2u);
    EXPECT_EQ(lf.objects("EQUIPMENT").size(), 1u);
    EXPECT_EQ(lf.objects("COMPUTATION").size(), 3u);
    EXPECT_EQ(lf.objects("CALIBRATION-MEASUREMENT").size(), 2u);
    EXPECT_EQ(lf.objects("CALIBRATION-COEFFICIENT").size(), 2u);
    EXPECT_EQ(lf.objects("CALIBRATION").size(), 1u);
    EXPECT_EQ(lf.objects("COMMENT").size(), 1u);
    EXPECT_EQ(lf.objects("MESSAGE").size(), 1u);
    EXPECT_EQ(lf.objects("NO-FORMAT").size(), 2u);
    // test_object_unknown
    const Object* unknown = object(lf, "UNKNOWN_SET", "OBJ1");
    ASSERT_NE(unknown, nullptr);
    EXPECT_EQ(unknown->name.origin, 10u);
}

// test_channel, test_frame, test_curves_values, test_parameter.
TEST(DlisCorpusTest, Chap4ChannelsFramesAndParameters) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const SemanticFile& file = semantic();
    const Outcome& out = file.out;
    ASSERT_FALSE(out.refused) << out.message;
    ASSERT_EQ(out.index.files.size(), 1u);
    const LogicalFile& lf = out.index.files[0];
    // CHANN1 is UNORM with dimension 2 x 3 x 4.
    const Channel* c1 = lf.channel(ObjectName{10, 0, "CHANN1"});
    ASSERT_NE(c1, nullptr);
    EXPECT_EQ(c1->repCode, kUNORM);
    EXPECT_EQ(c1->elements(), 24u);
    EXPECT_EQ(c1->dimension.size(), 3u);
    const Object* c1o = object(lf, "CHANNEL", "CHANN1");
    ASSERT_NE(c1o, nullptr);
    const Attribute* dim = c1o->attribute("DIMENSION");
    ASSERT_NE(dim, nullptr);
    ASSERT_EQ(dim->values.size(), 3u);
    EXPECT_EQ(dim->number(0), 2.0);
    EXPECT_EQ(dim->number(1), 3.0);
    EXPECT_EQ(dim->number(2), 4.0);
    // test_frame
    const std::size_t k1 = frameIndex(lf, "FRAME1");
    const std::size_t k2 = frameIndex(lf, "FRAME2");
    ASSERT_LT(k1, lf.frames.size());
    ASSERT_LT(k2, lf.frames.size());
    const Frame& f1 = lf.frames[k1];
    EXPECT_EQ(f1.indexType, "BOREHOLE-DEPTH");
    EXPECT_EQ(f1.direction, "DECREASING");
    ASSERT_EQ(f1.channels.size(), 2u);
    EXPECT_EQ(lf.channels[f1.channels[0]].name.id, "CHANN1");
    EXPECT_EQ(lf.channels[f1.channels[1]].name.id, "CHANN2");
    EXPECT_EQ(f1.records, 3u);
    const Frame& f2 = lf.frames[k2];
    EXPECT_TRUE(f2.channels.empty());
    EXPECT_EQ(f2.indexType, "");
    EXPECT_EQ(f2.direction, "");
    // test_curves_values: frame k (from 0) holds 1..24 + 512 k in CHANN1 and 257..280 + 512 k
    // in CHANN2.
    Diagnostics d;
    const std::vector<FrameRow> rows = readAll(file.bytes, "semantic.dlis", out.index, 0, k1, &d);
    ASSERT_EQ(rows.size(), 3u);
    for (std::size_t k = 0; k < rows.size(); ++k) {
        SCOPED_TRACE(k);
        EXPECT_EQ(rows[k].number, k + 1);
        ASSERT_EQ(rows[k].values.size(), 48u);
        for (std::size_t i = 0; i < 24; ++i) {
            EXPECT_EQ(rows[k].values[i], double(1 + i + 512 * k));
            EXPECT_EQ(rows[k].values[24 + i], double(257 + i + 512 * k));
        }
    }
    EXPECT_EQ(d.warningCount, 0u);
    // test_parameter: PARAM1's value is [101, 120].
    const Parameter* p1 = nullptr;
    for (const Parameter& p : lf.parameters)
        if (p.name.id == "PARAM1") p1 = &p;
    ASSERT_NE(p1, nullptr);
    ASSERT_GE(p1->values.size(), 2u);
    EXPECT_EQ(numbers(p1->values[0]), std::vector<double>{101});
    EXPECT_EQ(numbers(p1->values[1]), std::vector<double>{120});
}

namespace {

// test_curves_reprcodes.py: FRAME-REPRCODE (10, 0) of `rel` holds one channel of code `code`
// whose frames 1, 2, ... hold `expected` (NaN: not a number).
void expectReprcodeFrames(const std::string& rel, int code, const std::vector<double>& expected) {
    SCOPED_TRACE(rel);
    const std::string bytes = fileBytes(corpusPath(rel));
    const Outcome out = indexBytes(bytes, rel);
    ASSERT_FALSE(out.refused) << out.message;
    ASSERT_EQ(out.index.files.size(), 1u);
    const LogicalFile& lf = out.index.files[0];
    const std::size_t k = frameIndex(lf, "FRAME-REPRCODE");
    ASSERT_LT(k, lf.frames.size());
    EXPECT_EQ(lf.frames[k].name, (ObjectName{10, 0, "FRAME-REPRCODE"}));
    ASSERT_EQ(lf.frames[k].channels.size(), 1u);
    EXPECT_EQ(lf.channels[lf.frames[k].channels[0]].repCode, code);
    Diagnostics d;
    const std::vector<FrameRow> rows = readAll(bytes, rel, out.index, 0, k, &d);
    EXPECT_EQ(rows.size(), expected.size()) << warningsText(d);
    for (std::size_t i = 0; i < std::min(rows.size(), expected.size()); ++i) {
        EXPECT_EQ(rows[i].number, i + 1);
        ASSERT_EQ(rows[i].values.size(), 1u);
        if (std::isnan(expected[i])) {
            EXPECT_TRUE(std::isnan(rows[i].values[0])) << rows[i].values[0];
        } else {
            EXPECT_EQ(rows[i].values[0], expected[i]);
        }
    }
}

struct ReprcodeCase {
    const char* file;
    double first;   // reprcodes/: the one frame; reprcodes-x2/: the first of two
    double second;  // reprcodes-x2/: the second frame
};

// Numbers arrive as numbers (a compound one, value and bounds or real and imaginary, by its
// first component), the rest as NaN.
const std::vector<ReprcodeCase>& reprcodeCases() {
    static const std::vector<ReprcodeCase> cases = {
        {"01-fshort", -1, 153},
        {"02-fsingl", 5.5, -13.75},
        {"03-fsing1", -2, -2},
        {"04-fsing2", 117, 3524454},
        {"05-isingl", -12, 65536.5},
        {"06-vsingl", 0.125, -21.25},
        {"07-fdoubl", 900000000000000.5, -153},
        {"08-fdoub1", -13.5, 5673345},
        {"09-fdoub2", 6728332223, 95637722454},
        {"10-csingl", 93, 67},
        {"11-cdoubl", 125533556, 67},
        {"12-sshort", 89, -89},
        {"13-snorm", -153, 153},
        {"14-slong", 2147483647, -153},
        {"15-ushort", 6, 217},
        {"16-unorm", 32921, 256},
        {"17-ulong", 1, 4294967143},
        {"18-uvari", 257, 65536},
        {"19-ident", kNaN, kNaN},
        {"20-ascii", kNaN, kNaN},
        {"21-dtime", kNaN, kNaN},
        {"22-origin", 16777217, 3},
        {"23-obname", kNaN, kNaN},
        {"24-objref", kNaN, kNaN},
        {"25-attref", kNaN, kNaN},
        {"26-status", 1, 0},
        {"27-units", kNaN, kNaN},
    };
    return cases;
}

}  // namespace

// test_fshort ... test_units: one frame of one channel of each code.
TEST(DlisCorpusTest, Chap4FrameValuesOfEveryRepresentationCode) {
    CALIPER3D_REQUIRE_DATA(corpus());
    for (const ReprcodeCase& c : reprcodeCases())
        expectReprcodeFrames(std::string("chap4-7/iflr/reprcodes/") + c.file + ".dlis",
                             std::stoi(std::string(c.file).substr(0, 2)), {c.first});
}

// test_fshort_x2 ... test_units_x2: two frames in one frame data record.
TEST(DlisCorpusTest, Chap4TwoFramesInOneRecord) {
    CALIPER3D_REQUIRE_DATA(corpus());
    for (const ReprcodeCase& c : reprcodeCases())
        expectReprcodeFrames(std::string("chap4-7/iflr/reprcodes-x2/") + c.file + ".dlis",
                             std::stoi(std::string(c.file).substr(0, 2)), {c.first, c.second});
}

// test_all_reprcodes: one frame of 27 channels, one of each code.
TEST(DlisCorpusTest, Chap4FrameOfAllRepresentationCodes) {
    CALIPER3D_REQUIRE_DATA(corpus());
    const std::string rel = "chap4-7/iflr/all-reprcodes.dlis";
    const std::string bytes = fileBytes(corpusPath(rel));
    const Outcome out = indexBytes(bytes, rel);
    ASSERT_FALSE(out.refused) << out.message;
    const LogicalFile& lf = out.index.files.at(0);
    const std::size_t k = frameIndex(lf, "FRAME-REPRCODE");
    ASSERT_LT(k, lf.frames.size());
    ASSERT_EQ(lf.frames[k].channels.size(), 27u);
    for (std::size_t i = 0; i < 27; ++i)
        EXPECT_EQ(lf.channels[lf.frames[k].channels[i]].repCode, int(i + 1)) << i;
    Diagnostics d;
    const std::vector<FrameRow> rows = readAll(bytes, rel, out.index, 0, k, &d);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].number, 1u);
    const std::vector<double> expected = {
        -1,       5.5,        -2,   117,       -12,  0.125, 900000000000000.5,
        -13.5,    6728332223, 93,   125533556, 89,   -153,  2147483647,
        6,        32921,      1,    257,       kNaN, kNaN,  kNaN,
        16777217, kNaN,       kNaN, kNaN,      1,    kNaN};
    ASSERT_EQ(rows[0].values.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        if (std::isnan(expected[i])) {
            EXPECT_TRUE(std::isnan(rows[0].values[i])) << i;
        } else {
            EXPECT_EQ(rows[0].values[i], expected[i]) << i;
        }
    }
}

namespace {

// The frames of FRAME-REPRCODE in the first logical file of `rel`.
std::vector<FrameRow> reprcodeRows(const std::string& rel, Diagnostics* d) {
    const std::string bytes = fileBytes(corpusPath(rel));
    const Outcome out = indexBytes(bytes, rel);
    EXPECT_FALSE(out.refused) << out.message;
    if (out.refused || out.index.files.empty()) return {};
    const std::size_t k = frameIndex(out.index.files[0], "FRAME-REPRCODE");
    if (k >= out.index.files[0].frames.size()) return {};
    return readAll(bytes, rel, out.index, 0, k, d);
}

std::vector<std::uint32_t> frameNumbers(const std::vector<FrameRow>& rows) {
    std::vector<std::uint32_t> n;
    for (const FrameRow& r : rows) n.push_back(r.number);
    return n;
}

std::vector<double> column(const std::vector<FrameRow>& rows, std::size_t i) {
    std::vector<double> v;
    for (const FrameRow& r : rows) v.push_back(r.values.at(i));
    return v;
}

}  // namespace

// test_curves.py: frame numbers as recorded, out of order, missing or repeated.
TEST(DlisCorpusTest, Chap4FrameNumbersAsRecorded) {
    CALIPER3D_REQUIRE_DATA(corpus());
    Diagnostics d;
    {
        SCOPED_TRACE("out-of-order-framenos-one-frame");
        const auto rows = reprcodeRows("chap4-7/iflr/out-of-order-framenos-one-frame.dlis", &d);
        EXPECT_EQ(frameNumbers(rows), (std::vector<std::uint32_t>{2, 1}));
        EXPECT_EQ(column(rows, 0), (std::vector<double>{1, 0}));
    }
    {
        SCOPED_TRACE("out-of-order-framenos-two-frames");
        const auto rows = reprcodeRows("chap4-7/iflr/out-of-order-framenos-two-frames.dlis", &d);
        EXPECT_EQ(frameNumbers(rows), (std::vector<std::uint32_t>{2, 1}));
        EXPECT_EQ(column(rows, 0), (std::vector<double>{1, 0}));
    }
    {
        SCOPED_TRACE("out-of-order-framenos-two-frames-multifdata");
        const auto rows =
            reprcodeRows("chap4-7/iflr/out-of-order-framenos-two-frames-multifdata.dlis", &d);
        EXPECT_EQ(frameNumbers(rows), (std::vector<std::uint32_t>{3, 4, 1, 2}));
        EXPECT_EQ(column(rows, 0), (std::vector<double>{1, 0, 0, 1}));
    }
    {
        SCOPED_TRACE("missing-framenos");
        const auto rows = reprcodeRows("chap4-7/iflr/missing-framenos.dlis", &d);
        EXPECT_EQ(frameNumbers(rows), (std::vector<std::uint32_t>{2, 4}));
        EXPECT_EQ(column(rows, 0), (std::vector<double>{1, 0}));
    }
    {
        SCOPED_TRACE("duplicate-framenos");
        const auto rows = reprcodeRows("chap4-7/iflr/duplicate-framenos.dlis", &d);
        ASSERT_EQ(rows.size(), 2u);
        EXPECT_EQ(rows[0].number, rows[1].number);
        EXPECT_EQ(column(rows, 0), (std::vector<double>{1, 0}));
    }
    {
        SCOPED_TRACE("duplicate-framenos-same-frames");
        const auto rows = reprcodeRows("chap4-7/iflr/duplicate-framenos-same-frames.dlis", &d);
        ASSERT_EQ(rows.size(), 2u);
        EXPECT_EQ(rows[0].values, rows[1].values);
    }
}

// test_various_fdata_in_one_iflr, test_dimensions_in_multifdata: several frames in one frame
// data record.
TEST(DlisCorpusTest, Chap4SeveralFramesInOneRecord) {
    CALIPER3D_REQUIRE_DATA(corpus());
    Diagnostics d;
    {
        // test_various_fdata_in_one_iflr: DTIME, IDENT, SSHORT in three frames of one record.
        SCOPED_TRACE("various-fdata-in-one-iflr");
        const auto rows = reprcodeRows("chap4-7/iflr/various-fdata-in-one-iflr.dlis", &d);
        EXPECT_EQ(rows.size(), 3u);
        if (!rows.empty()) {
            EXPECT_EQ(column(rows, 2), (std::vector<double>{89, -89, 122}));
            EXPECT_TRUE(std::isnan(rows[0].values[0]));
            EXPECT_TRUE(std::isnan(rows[0].values[1]));
        }
    }
    {
        // test_dimensions_in_multifdata: a 2 x 3 array per frame, 1..6 then 7..12.
        SCOPED_TRACE("multidimensions-multifdata");
        const std::string rel = "chap4-7/iflr/multidimensions-multifdata.dlis";
        const std::string bytes = fileBytes(corpusPath(rel));
        const Outcome out = indexBytes(bytes, rel);
        ASSERT_FALSE(out.refused) << out.message;
        const LogicalFile& lf = out.index.files.at(0);
        const std::size_t k = frameIndex(lf, "FRAME-DIMENSION");
        ASSERT_LT(k, lf.frames.size());
        EXPECT_EQ(lf.frames[k].name.origin, 11u);
        const auto rows = readAll(bytes, rel, out.index, 0, k, &d);
        ASSERT_EQ(rows.size(), 2u);
        EXPECT_EQ(rows[0].values, (std::vector<double>{1, 2, 3, 4, 5, 6}));
        EXPECT_EQ(rows[1].values, (std::vector<double>{7, 8, 9, 10, 11, 12}));
    }
}

// test_dimensions: integers in arrays of several shapes.
TEST(DlisCorpusTest, Chap4ArraysInFrames) {
    CALIPER3D_REQUIRE_DATA(corpus());
    Diagnostics d;
    {
        // test_dimensions: integers in arrays of several shapes, first frame.
        SCOPED_TRACE("multidimensions-ints-various");
        const std::string rel = "chap4-7/iflr/multidimensions-ints-various.dlis";
        const std::string bytes = fileBytes(corpusPath(rel));
        const Outcome out = indexBytes(bytes, rel);
        ASSERT_FALSE(out.refused) << out.message;
        const LogicalFile& lf = out.index.files.at(0);
        ASSERT_FALSE(lf.frames.empty());
        const auto rows = readAll(bytes, rel, out.index, 0, 0, &d);
        ASSERT_FALSE(rows.empty());
        // [[1,2,3],[4,5,6]], [[1,2],[3,4],[5,6]] open the frame.
        ASSERT_GE(rows[0].values.size(), 12u);
        EXPECT_EQ(std::vector<double>(rows[0].values.begin(), rows[0].values.begin() + 12),
                  (std::vector<double>{1, 2, 3, 4, 5, 6, 1, 2, 3, 4, 5, 6}));
    }
}

// test_error_handler.py: frame data records short of a frame are skipped with a warning.
TEST(DlisCorpusTest, Chap4RecordsShortOfAFrame) {
    CALIPER3D_REQUIRE_DATA(corpus());
    {
        // test_curves_broken_fmt: the second record is short of a frame; frames 1 and 3.
        SCOPED_TRACE("broken-fmt");
        Diagnostics bd;
        const auto rows = reprcodeRows("chap4-7/iflr/broken-fmt.dlis", &bd);
        EXPECT_EQ(frameNumbers(rows), (std::vector<std::uint32_t>{1, 3}));
        EXPECT_GT(bd.warningCount, 0u);
        for (const Warning& w : bd.warnings) EXPECT_EQ(w.file, "chap4-7/iflr/broken-fmt.dlis");
    }
    {
        // test_curves_broken_fmt_in_multirecord_frame: the whole frames of the short record
        // are kept.
        SCOPED_TRACE("broken-fmt-multiframe");
        Diagnostics bd;
        const auto rows = reprcodeRows("chap4-7/iflr/broken-fmt-multiframe.dlis", &bd);
        EXPECT_EQ(frameNumbers(rows), (std::vector<std::uint32_t>{1, 2, 3, 4, 5, 7, 8, 9}));
        EXPECT_GT(bd.warningCount, 0u);
    }
}

// ---------------------------------------------------------------------------------------------
// 3. The real file: a sidewall coring station log (Faroe Petroleum 206/05a-3, Fulla, 2011).

namespace {

struct RealFile {
    std::string bytes;
    Outcome out;
};

const RealFile& realFile() {
    static const RealFile file = [] {
        RealFile f;
        f.bytes = fileBytes(corpusPath(kRealFile));
        f.out = indexBytes(f.bytes, kRealFile);
        return f;
    }();
    return file;
}

std::vector<std::string> channelIds(const LogicalFile& lf, const Frame& f) {
    std::vector<std::string> ids;
    for (std::size_t c : f.channels) ids.push_back(lf.channels.at(c).name.id);
    return ids;
}

}  // namespace

// dlisio's test_core.py (before 025cea9): the label, the file header and the defining origin.
TEST(DlisRealFileTest, LabelHeaderAndOrigin) {
    CALIPER3D_REQUIRE_DATA(corpus() / kRealFile);
    const RealFile& f = realFile();
    ASSERT_FALSE(f.out.refused) << f.out.message;
    const DlisIndex& index = f.out.index;
    EXPECT_TRUE(index.hasSul);
    EXPECT_EQ(index.sulOffset, 0u);
    EXPECT_EQ(index.version, "V1.00");
    EXPECT_EQ(index.structure, "RECORD");
    EXPECT_EQ(index.maxRecordLength, 8192u);
    EXPECT_EQ(trimmed(index.storageSetId), "Default Storage Set");
    EXPECT_FALSE(index.tapeImage);
    ASSERT_EQ(index.files.size(), 1u);
    const LogicalFile& lf = index.files[0];
    // The file header is the first record: its segment header follows the label (80 bytes)
    // and the first visible record's header (4 bytes).
    ASSERT_FALSE(lf.sets.empty());
    EXPECT_EQ(lf.sets[0].type, "FILE-HEADER");
    EXPECT_EQ(lf.sets[0].offset, 84u);
    EXPECT_EQ(lf.offset, 84u);
    // dlisio's test_file_properties (before 2019): 3252 logical records. 921 + 2301 of them
    // are frame data (one frame each), the rest sets, some of them encrypted.
    EXPECT_EQ(lf.frameRecords, 921u + 2301u);
    EXPECT_EQ(lf.unknownFrameRecords, 0u);
    EXPECT_EQ(lf.otherRecords, 0u);
    EXPECT_GT(lf.encryptedRecords, 0u);
    EXPECT_EQ(lf.sets.size() + lf.encryptedRecords + lf.frameRecords, 3252u);
    EXPECT_EQ(trimmed(lf.id), "MSCT_197LTP");
    const Object* fh = object(lf, "FILE-HEADER", "5");
    ASSERT_NE(fh, nullptr);
    EXPECT_EQ(fh->name, (ObjectName{2, 0, "5"}));
    EXPECT_EQ(trimmed(fh->attribute("SEQUENCE-NUMBER")->text()), "197");
    EXPECT_EQ(lf.wellName, "206/05a-3");
    EXPECT_EQ(lf.wellId, "");
    EXPECT_EQ(lf.fieldName, "Fulla");
    EXPECT_EQ(lf.company, "Faroe Petroleum");
    EXPECT_EQ(lf.producer, "Schlumberger");
    EXPECT_EQ(lf.product, "OP");
    // 2011-08-20 22:48:50, daylight saving time (TotalDepth's export: "22:48:50.000 DST").
    EXPECT_EQ(lf.creationTime, "2011-08-20 22:48:50.000 local daylight savings");
    const Object* origin = object(lf, "ORIGIN", "DLIS_DEFINING_ORIGIN");
    ASSERT_NE(origin, nullptr);
    EXPECT_EQ(origin->name, (ObjectName{2, 0, "DLIS_DEFINING_ORIGIN"}));
    EXPECT_EQ(trimmed(origin->attribute("FILE-ID")->text()), "MSCT_197LTP");
    EXPECT_EQ(trimmed(origin->attribute("FILE-SET-NAME")->text()), "FAROE_PETROLEUM/206_05A-3");
    EXPECT_EQ(origin->attribute("FILE-SET-NUMBER")->number(), 41.0);
    EXPECT_EQ(origin->attribute("FILE-NUMBER")->number(), 167.0);
    EXPECT_EQ(trimmed(origin->attribute("FILE-TYPE")->text()), "STATION LOG");
    EXPECT_EQ(trimmed(origin->attribute("VERSION")->text()), "19C0-187");
    EXPECT_EQ(origin->attribute("PROGRAMS")->values.size(), 4u);
    EXPECT_EQ(trimmed(origin->attribute("ORDER-NUMBER")->text()), "BSAX-00003");
    EXPECT_EQ(trimmed(origin->attribute("DESCENT-NUMBER")->text()), "-1");
    EXPECT_EQ(trimmed(origin->attribute("RUN-NUMBER")->text()), "1");
    EXPECT_EQ(origin->attribute("PRODUCER-CODE")->number(), 440.0);
    EXPECT_EQ(trimmed(origin->attribute("NAME-SPACE-NAME")->text()), "SLB");
}

// test_channel, test_frame, test_channel_order, test_fmtstring, test_dtype (dlisio before
// 025cea9); the frame counts from TotalDepth's export ("frames 921 out of 921", "2,301").
TEST(DlisRealFileTest, FramesAndChannels) {
    CALIPER3D_REQUIRE_DATA(corpus() / kRealFile);
    const RealFile& f = realFile();
    ASSERT_FALSE(f.out.refused) << f.out.message;
    const LogicalFile& lf = f.out.index.files.at(0);
    const Channel* tdep = lf.channel(ObjectName{2, 0, "TDEP"});
    ASSERT_NE(tdep, nullptr);
    EXPECT_EQ(tdep->longName, "6-Inch Frame Depth");
    EXPECT_EQ(tdep->repCode, kFSINGL);
    EXPECT_EQ(tdep->dimension, (std::vector<std::uint32_t>{1}));
    EXPECT_EQ(tdep->units, "0.1 in");

    const std::size_t k2000 = frameIndex(lf, "2000T");
    const std::size_t k800 = frameIndex(lf, "800T");
    ASSERT_LT(k2000, lf.frames.size());
    ASSERT_LT(k800, lf.frames.size());
    const Frame& f2000 = lf.frames[k2000];
    EXPECT_EQ(f2000.name, (ObjectName{2, 0, "2000T"}));
    EXPECT_EQ(f2000.indexType, "TIME");
    EXPECT_EQ(f2000.direction, "INCREASING");
    EXPECT_EQ(channelIds(lf, f2000),
              (std::vector<std::string>{"TIME", "TDEP", "TENS_SL", "DEPT_SL"}));
    for (std::size_t c : f2000.channels) EXPECT_EQ(lf.channels[c].repCode, kFSINGL);
    EXPECT_EQ(f2000.frameBytes, 16u);
    EXPECT_EQ(f2000.records, 921u);

    const Frame& f800 = lf.frames[k800];
    const std::vector<std::string> ref800 = {
        "TIME", "TDEP", "ETIM", "LMVL", "UMVL", "CFLA", "OCD",  "RCMD", "RCPP", "CMRT", "RCNU",
        "DCFL", "DFS",  "DZER", "RHMD", "HMRT", "RHV",  "RLSW", "MNU",  "S1CY", "S2CY", "RSCU",
        "RSTS", "UCFL", "CARC", "CMDV", "CMPP", "CNU",  "HMDV", "HV",   "LSWI", "SCUR", "SSTA",
        "RCMP", "RHPP", "RRPP", "CMPR", "HPPR", "RPPV", "SMSC", "CMCU", "HMCU", "CMLP"};
    EXPECT_EQ(channelIds(lf, f800), ref800);
    // "iffff...flfff": every channel FSINGL but SMSC, an SLONG.
    for (std::size_t i = 0; i < f800.channels.size(); ++i)
        EXPECT_EQ(lf.channels[f800.channels[i]].repCode, ref800[i] == "SMSC" ? kSLONG : kFSINGL)
            << ref800[i];
    EXPECT_EQ(f800.frameBytes, 43u * 4u);
    EXPECT_EQ(f800.records, 2301u);
}

// test_frame_getitem (dlisio before 025cea9): the first frame of 2000T is
// [16677259, 852606, 2233, 852606]; TotalDepth's export: 921 frames, TIME to 17597260 ms,
// TDEP 852606..893302, TENS_SL 1825..2594 lbf (mean 2145.789), DEPT_SL up to 893303 (mean
// 872467.701).
TEST(DlisRealFileTest, CurveValuesOfFrame2000T) {
    CALIPER3D_REQUIRE_DATA(corpus() / kRealFile);
    const RealFile& f = realFile();
    ASSERT_FALSE(f.out.refused) << f.out.message;
    const LogicalFile& lf = f.out.index.files.at(0);
    const std::size_t k = frameIndex(lf, "2000T");
    ASSERT_LT(k, lf.frames.size());
    Diagnostics d;
    const std::vector<FrameRow> rows = readAll(f.bytes, kRealFile, f.out.index, 0, k, &d);
    EXPECT_EQ(d.warningCount, 0u);
    ASSERT_EQ(rows.size(), 921u);
    EXPECT_EQ(rows[0].number, 1u);
    EXPECT_EQ(rows[0].values, (std::vector<double>{16677259.0, 852606.0, 2233.0, 852606.0}));
    EXPECT_EQ(rows.back().number, 921u);
    EXPECT_EQ(rows.back().values[0], 17597260.0);
    double minV[4], maxV[4], sum[4] = {0, 0, 0, 0};
    for (int c = 0; c < 4; ++c) {
        minV[c] = std::numeric_limits<double>::infinity();
        maxV[c] = -minV[c];
    }
    for (const FrameRow& r : rows)
        for (int c = 0; c < 4; ++c) {
            minV[c] = std::min(minV[c], r.values[c]);
            maxV[c] = std::max(maxV[c], r.values[c]);
            sum[c] += r.values[c];
        }
    EXPECT_EQ(minV[0], 16677259.0);
    EXPECT_EQ(maxV[0], 17597260.0);
    EXPECT_NEAR(sum[0] / 921, 17137259.891, 0.001);
    EXPECT_EQ(minV[1], 852606.0);
    EXPECT_EQ(maxV[1], 893302.0);
    EXPECT_NEAR(sum[1] / 921, 872468.704, 0.001);
    EXPECT_EQ(minV[2], 1825.0);
    EXPECT_EQ(maxV[2], 2594.0);
    EXPECT_NEAR(sum[2] / 921, 2145.789, 0.001);
    EXPECT_EQ(minV[3], 852606.0);
    EXPECT_EQ(maxV[3], 893303.0);
    EXPECT_NEAR(sum[3] / 921, 872467.701, 0.001);
}

// TotalDepth's LAS export of frame 800T: 2301 frames; the first and the last row.
TEST(DlisRealFileTest, CurveValuesOfFrame800T) {
    CALIPER3D_REQUIRE_DATA(corpus() / kRealFile);
    const RealFile& f = realFile();
    ASSERT_FALSE(f.out.refused) << f.out.message;
    const LogicalFile& lf = f.out.index.files.at(0);
    const std::size_t k = frameIndex(lf, "800T");
    ASSERT_LT(k, lf.frames.size());
    // Only some channels wanted: TIME, ETIM, OCD, SMSC (SLONG), CMLP.
    const Frame& fr = lf.frames[k];
    const FrameRead wanted = frameRead(lf, fr, {0, 2, 6, 39, 42});
    ASSERT_EQ(wanted.width, 5u);
    std::vector<FrameRow> rows;
    Diagnostics d;
    readFrames(
        f.bytes, kRealFile, f.out.index, 0, k, wanted,
        [&](std::uint32_t number, const double* values, std::size_t offset) {
            EXPECT_GT(offset, 80u);
            EXPECT_LT(offset, f.bytes.size());
            rows.push_back({number, std::vector<double>(values, values + 5)});
            return true;
        },
        &d);
    EXPECT_EQ(d.warningCount, 0u);
    ASSERT_EQ(rows.size(), 2301u);
    EXPECT_EQ(rows[0].number, 1u);
    EXPECT_EQ(rows[0].values[0], 16677259.0);
    EXPECT_EQ(rows[0].values[1], 0.0);
    EXPECT_NEAR(rows[0].values[2], 6789.050, 0.0005);
    EXPECT_EQ(rows[0].values[3], 192.0);
    EXPECT_NEAR(rows[0].values[4], -0.909, 0.0005);
    EXPECT_EQ(rows[2300].number, 2301u);
    EXPECT_EQ(rows[2300].values[0], 17597260.0);
    EXPECT_NEAR(rows[2300].values[1], 920.001, 0.0005);
    EXPECT_NEAR(rows[2300].values[2], 7433.008, 0.0005);
    EXPECT_EQ(rows[2300].values[3], 192.0);
    EXPECT_NEAR(rows[2300].values[4], -0.909, 0.0005);
    // Stopping early stops.
    std::size_t seen = 0;
    readFrames(
        f.bytes, kRealFile, f.out.index, 0, k, wanted,
        [&](std::uint32_t, const double*, std::size_t) { return ++seen < 10; }, &d);
    EXPECT_EQ(seen, 10u);
}

// test_parameters, test_tools, test_equipment, test_measurement, test_coefficient,
// test_calibrations (dlisio before 025cea9); test_load_unknowns: five set types dlisio does not
// know; TotalDepth's export for TREF and CPPL.
TEST(DlisRealFileTest, ParametersAndOtherObjects) {
    CALIPER3D_REQUIRE_DATA(corpus() / kRealFile);
    const RealFile& f = realFile();
    ASSERT_FALSE(f.out.refused) << f.out.message;
    const LogicalFile& lf = f.out.index.files.at(0);
    EXPECT_EQ(lf.parameters.size(), 226u);
    EXPECT_EQ(lf.objects("PARAMETER").size(), 226u);
    auto param = [&](const std::string& id) -> const Parameter* {
        for (const Parameter& p : lf.parameters)
            if (p.name.id == id) return &p;
        return nullptr;
    };
    const Parameter* flsh = param("FLSHSTRM");
    ASSERT_NE(flsh, nullptr);
    EXPECT_EQ(flsh->name, (ObjectName{2, 0, "FLSHSTRM"}));
    EXPECT_EQ(flsh->longName, "Flush depth-delayed streams to output at end");
    ASSERT_FALSE(flsh->values.empty());
    EXPECT_EQ(std::get<std::string>(flsh->values[0]), "DOWNLOG_ONLY");
    const Parameter* tref = param("TREF");
    ASSERT_NE(tref, nullptr);
    EXPECT_EQ(tref->units, "lbf");
    ASSERT_FALSE(tref->values.empty());
    EXPECT_EQ(numbers(tref->values[0]), std::vector<double>{1000.0});
    const Parameter* cppl = param("CPPL");
    ASSERT_NE(cppl, nullptr);
    EXPECT_EQ(cppl->units, "psi");
    EXPECT_EQ(cppl->longName, "Core Pushing Pressure Limit");
    ASSERT_FALSE(cppl->values.empty());
    EXPECT_EQ(numbers(cppl->values[0]), std::vector<double>{5014.69580078125});

    EXPECT_EQ(lf.objects("TOOL").size(), 2u);
    const Object* tool = object(lf, "TOOL", "MSCT");
    ASSERT_NE(tool, nullptr);
    EXPECT_EQ(tool->attribute("DESCRIPTION")->text(), "Mechanical Sidewall Coring Tool");
    EXPECT_EQ(tool->attribute("TRADEMARK-NAME")->text(), "MSCT-AA");
    EXPECT_EQ(tool->attribute("GENERIC-NAME")->text(), "MSCT");
    EXPECT_EQ(tool->attribute("STATUS")->number(), 1.0);
    EXPECT_EQ(tool->attribute("PARAMETERS")->values.size(), 22u);
    EXPECT_EQ(tool->attribute("CHANNELS")->values.size(), 74u);
    EXPECT_EQ(tool->attribute("PARTS")->values.size(), 9u);

    EXPECT_EQ(lf.objects("EQUIPMENT").size(), 14u);
    const Object* e = object(lf, "EQUIPMENT", "MSCT/MCFU_1/EQUIPMENT");
    ASSERT_NE(e, nullptr);
    EXPECT_EQ(e->attribute("TRADEMARK-NAME")->text(), "MCFU_1-AA");
    EXPECT_EQ(e->attribute("SERIAL-NUMBER")->text(), "119.");
    EXPECT_EQ(e->attribute("LENGTH")->number(), 125.0);
    EXPECT_EQ(e->attribute("MINIMUM-DIAMETER")->number(), 5.25);
    EXPECT_EQ(e->attribute("VOLUME")->number(), 1.5700000524520874);
    EXPECT_EQ(e->attribute("WEIGHT")->number(), 144.0);
    EXPECT_EQ(e->attribute("PRESSURE")->number(), 20000.0);
    EXPECT_EQ(e->attribute("TEMPERATURE")->number(), 350.0);

    EXPECT_EQ(lf.objects("CALIBRATION-MEASUREMENT").size(), 6u);
    const Object* m = object(lf, "CALIBRATION-MEASUREMENT", "MSCT_SGTE/ZM_BEF/CALI_MEAS");
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(m->attribute("PHASE")->text(), "BEFORE");
    EXPECT_EQ(m->attribute("SAMPLE-COUNT")->number(), 142.0);
    EXPECT_EQ(m->attribute("BEGIN-TIME")->text().substr(0, 19), "2011-08-20 18:13:38");
    EXPECT_EQ(m->attribute("DURATION")->number(), 30.0);
    EXPECT_EQ(m->attribute("MEASUREMENT")->number(), 2.640824317932129);
    EXPECT_EQ(m->attribute("MAXIMUM-DEVIATION")->number(), 11.421565055847168);
    EXPECT_EQ(m->attribute("STANDARD-DEVIATION")->number(), 3.4623820781707764);
    EXPECT_EQ(m->attribute("REFERENCE")->number(), 0.0);

    EXPECT_EQ(lf.objects("CALIBRATION-COEFFICIENT").size(), 24u);
    const Object* c = object(lf, "CALIBRATION-COEFFICIENT", "GAIN-MSCT/HPPR/CALIBRATION");
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->attribute("LABEL")->text(), "GAIN");
    ASSERT_NE(c->attribute("COEFFICIENTS"), nullptr);
    EXPECT_EQ(c->attribute("COEFFICIENTS")->values.size(), 1u);
    EXPECT_EQ(c->attribute("COEFFICIENTS")->number(), 1.0);

    const Object* cal = object(lf, "CALIBRATION", "CNU");
    ASSERT_NE(cal, nullptr);
    EXPECT_EQ(cal->attribute("COEFFICIENTS")->values.size(), 2u);
    EXPECT_EQ(cal->attribute("CALIBRATED-CHANNELS")->values.size(), 1u);
    EXPECT_EQ(cal->attribute("UNCALIBRATED-CHANNELS")->values.size(), 1u);

    std::set<std::string> unknownTypes;
    for (const Set& s : lf.sets)
        if (!dlisioKnownTypes().count(s.type)) unknownTypes.insert(s.type);
    EXPECT_EQ(unknownTypes.size(), 5u);
    for (const std::string& t : unknownTypes) std::cout << "[ dlis unknown set ] " << t << "\n";
}

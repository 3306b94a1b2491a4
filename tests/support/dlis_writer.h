#pragma once

// A small DLIS (RP66 v1) writer for tests: the storage unit label, visible records, logical
// record segments (padding, checksums, trailing lengths, records split over segments and
// visible records, encrypted records), the tape-image wrapper, and the explicitly formatted
// sets (FILE-HEADER, ORIGIN, CHANNEL, FRAME, PARAMETER) and frame data a log needs.
// Independent of io's reader: what it writes is built from RP66 v1 itself (the storage
// unit label and visible records of section 2.3, logical record segments of 2.2, set,
// template and object components of 3.2, representation codes of Appendix B).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace caliper3d::test::dlis {

// Representation codes (RP66 v1 Appendix B), by number.
enum Code : int {
    FSHORT = 1,
    FSINGL = 2,
    FSING1 = 3,
    FSING2 = 4,
    ISINGL = 5,
    VSINGL = 6,
    FDOUBL = 7,
    FDOUB1 = 8,
    FDOUB2 = 9,
    CSINGL = 10,
    CDOUBL = 11,
    SSHORT = 12,
    SNORM = 13,
    SLONG = 14,
    USHORT = 15,
    UNORM = 16,
    ULONG = 17,
    UVARI = 18,
    IDENT = 19,
    ASCII = 20,
    DTIME = 21,
    ORIGIN = 22,
    OBNAME = 23,
    OBJREF = 24,
    ATTREF = 25,
    STATUS = 26,
    UNITS = 27
};
// Components of one value of a numeric code: 2 for FSING1, FDOUB1, CSINGL, CDOUBL; 3 for
// FSING2, FDOUB2; else 1.
int components(int code);

// ---- Values in their codes (big-endian, as RP66 v1 writes them) ----
// A number in a numeric code (1..18, 22 ORIGIN, 26 STATUS): integers rounded; a compound
// code's one component. Throws std::invalid_argument for a text or name code.
void putNumber(std::string& out, int code, double value);
void putUvari(std::string& out, std::uint32_t value, int width = 0);  // width 0: shortest
void putIdent(std::string& out, const std::string& text);             // also UNITS
void putAscii(std::string& out, const std::string& text);
// "YYYY-MM-DD hh:mm:ss[.mmm][ GMT| local daylight savings]" (time zone 0, local standard,
// when none is named).
void putDtime(std::string& out, const std::string& text);

struct Name {
    std::uint32_t origin = 1;
    std::uint8_t copy = 0;
    std::string id;
};
void putObname(std::string& out, const Name& name);

// The values of one attribute, all in one code.
struct Values {
    int code = IDENT;
    std::vector<double> numbers;     // numeric codes; a compound code's components in turn
    std::vector<std::string> texts;  // IDENT, ASCII, UNITS, DTIME
    std::vector<Name> names;         // OBNAME
    std::uint32_t count() const;     // values (a compound value counts once)
};
Values numbers(int code, std::vector<double> values);
Values texts(int code, std::vector<std::string> values);
Values names(std::vector<Name> values);

// One attribute component (RP66 v1 3.2.2.1): in a template with its label and defaults, in
// an object with what differs from them. What is not written comes from the template: count
// 1, code IDENT, no units, no value unless the template gives them.
struct Attr {
    std::string label;
    Values values;
    std::string units;
    bool absent = false;  // an absent attribute (ABSATR: nothing but its descriptor)
    bool writeLabel = true, writeCount = true, writeCode = true, writeUnits = true,
         writeValue = true;
};
// A template attribute or an object's attribute written in full (label only in templates;
// units only when not empty; value only when there are values).
Attr attr(const std::string& label, Values values, const std::string& units = "");
// An object's attribute that takes everything from the template (descriptor alone).
Attr fromTemplate();
// An object's attribute giving its value only (count and code from the template).
Attr valueOnly(Values values);
Attr absentAttr();

struct Object {
    Name name;
    std::vector<Attr> attrs;  // in template order; fewer than the template: the rest default
};

struct Set {
    std::string type;
    std::string name;  // written when not empty
    std::vector<Attr> templ;
    std::vector<Object> objects;
    enum Role { Normal, Replacement, Redundant } role = Normal;
};
// The body of an explicitly formatted logical record holding `set`.
std::string encodeSet(const Set& set);

// One logical record.
struct Record {
    bool explicitFormat = true;  // EFLR; false: indirectly formatted (IFLR)
    int type = 0;
    std::string body;
    bool encrypted = false;  // written with an encryption packet; body left as given
};

// ---- What a log holds ----
struct ChannelSpec {
    std::string name;
    std::string units;
    std::string longName;
    int code = FSINGL;
    std::vector<std::uint32_t> dimension = {1};
    std::size_t elements() const;
};

struct FrameSpec {
    std::string name = "MAIN";
    std::string indexType = "BOREHOLE-DEPTH";
    std::string direction = "INCREASING";  // "" leaves the attribute absent
    std::vector<ChannelSpec> channels;     // the first is the index
    // Row-major frame values: per frame every element of every channel, in channel order
    // (a compound code's first component; the others are written as 0).
    std::vector<double> values;
    std::size_t width() const;  // elements per frame
    std::size_t frames() const { return width() ? values.size() / width() : 0; }
    void addRow(const std::vector<double>& row);
};

struct ParameterSpec {
    std::string name;
    std::string units;
    std::string longName;
    std::vector<double> numbers;     // written as `code` (FDOUBL by default)
    std::vector<std::string> texts;  // written as ASCII when there are no numbers
    int code = FDOUBL;
};

struct LogicalFileSpec {
    std::string fileId = "CALIPER3D TEST";
    std::uint32_t origin = 41;  // every object's origin; above 127 it takes a 2-byte UVARI
    std::string wellName, wellId, fieldName, company, producerName = "caliper3d tests";
    std::string product = "caliper3d dlis_writer";
    std::string creationTime = "2024-03-05 14:07:30.250";
    int runNumber = 1;
    std::vector<ParameterSpec> parameters;
    std::vector<FrameSpec> frames;
    std::vector<Record> extraRecords;  // written after the frame set, before frame data
};

struct WriteOptions {
    std::string storageSetId = "CALIPER3D TEST STORAGE SET";
    std::size_t visibleRecordLength = 8192;  // most bytes per visible record (the label's)
    std::size_t segmentBody = 0;             // most body bytes per segment (0: as space allows)
    bool padAlways = false;  // pad every segment (else only to an even length of 16 or more)
    bool checksums = false;
    bool trailingLength = false;
    bool wideUvari = false;               // frame numbers as 4-byte UVARI, as some writers do
    bool tapeImage = false;               // wrapped in tape-image marks
    std::size_t tapeRecordLength = 8192;  // data bytes per tape-image record
    std::string leadingGarbage;           // bytes before the storage unit label
    bool encryptedRecord = false;         // one encrypted record after each file's origin
};

// The RP66 v1 16-bit checksum of `bytes` (Appendix C: 16-bit words, the first byte of each
// pair the low-order one, added with the carry folded back, the sum rotated left one bit
// after each word).
std::uint16_t checksum16(const std::string& bytes);

// The logical records of one logical file, in order (`sequence`: its FILE-HEADER's
// SEQUENCE-NUMBER, 1 for the first file of a storage unit).
std::vector<Record> logicalFileRecords(const LogicalFileSpec& file, const WriteOptions& options,
                                       std::size_t sequence = 1);
// A storage unit: label, then the records in visible records (and tape marks, garbage).
std::string writeStorageUnit(const std::vector<Record>& records, const WriteOptions& options);
std::string writeDlis(const std::vector<LogicalFileSpec>& files, const WriteOptions& options = {});
// The same to a file; throws std::runtime_error naming it when it cannot be written.
void writeDlisFile(const std::string& path, const std::vector<LogicalFileSpec>& files,
                   const WriteOptions& options = {});

// What a structural check of written bytes finds (visible records and segments walked from
// the label, tape marks removed first).
struct Layout {
    std::size_t visibleRecords = 0;
    std::size_t segments = 0;
    std::size_t records = 0;  // logical records (segments without a successor)
    std::string error;        // "" when every length adds up
};
Layout checkLayout(const std::string& bytes);

}  // namespace caliper3d::test::dlis

#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace caliper3d::io::dlis {

// The 27 representation codes of RP66 v1 (Appendix B), by number.
enum RepCode : int {
    kFSHORT = 1,
    kFSINGL = 2,
    kFSING1 = 3,
    kFSING2 = 4,
    kISINGL = 5,
    kVSINGL = 6,
    kFDOUBL = 7,
    kFDOUB1 = 8,
    kFDOUB2 = 9,
    kCSINGL = 10,
    kCDOUBL = 11,
    kSSHORT = 12,
    kSNORM = 13,
    kSLONG = 14,
    kUSHORT = 15,
    kUNORM = 16,
    kULONG = 17,
    kUVARI = 18,
    kIDENT = 19,
    kASCII = 20,
    kDTIME = 21,
    kORIGIN = 22,
    kOBNAME = 23,
    kOBJREF = 24,
    kATTREF = 25,
    kSTATUS = 26,
    kUNITS = 27
};
// "FSINGL"; "code 99" for a number outside 1..27.
std::string repCodeName(int code);
// Bytes of one value; 0 for the codes of variable size (UVARI, ORIGIN, the texts, names).
std::size_t repCodeSize(int code);

// An object's name (OBNAME): origin, copy number and identifier.
struct ObjectName {
    std::uint32_t origin = 0;
    std::uint8_t copy = 0;
    std::string id;
    bool operator==(const ObjectName& o) const {
        return origin == o.origin && copy == o.copy && id == o.id;
    }
    bool operator!=(const ObjectName& o) const { return !(*this == o); }
};
// OBJREF: an object of a given set type.
struct ObjectRef {
    std::string type;
    ObjectName name;
};
// ATTREF: an attribute of an object.
struct AttributeRef {
    std::string type;
    ObjectName name;
    std::string label;
};

// One value of an attribute, in the form its code decodes to: numbers (integers, the
// floats, STATUS, ORIGIN, UVARI) as double; the compound numbers (FSING1, FSING2, FDOUB1,
// FDOUB2: value then bounds; CSINGL, CDOUBL: real then imaginary) as their components;
// IDENT, ASCII and UNITS as text, DTIME as "YYYY-MM-DD hh:mm:ss.mmm" (its time zone after a
// space: "local standard", "local daylight savings" or "GMT"); the names and references.
using Value =
    std::variant<double, std::vector<double>, std::string, ObjectName, ObjectRef, AttributeRef>;

// One attribute of an object (or of a set's template).
struct Attribute {
    std::string label;
    std::uint32_t count = 1;
    int repCode = kIDENT;
    std::string units;
    std::vector<Value> values;  // empty when the attribute has no value
    bool absent = false;        // an absent attribute (ABSATR): no count, code or value
    bool invariant = false;     // a template's invariant attribute, the same for every object

    // The i-th value as a number (the first component of a compound); NaN when there is
    // none or it is not a number.
    double number(std::size_t i = 0) const;
    // The i-th value as text (numbers written shortest, names by identifier, leading
    // and trailing blanks dropped); "" when none.
    std::string text(std::size_t i = 0) const;
};

struct Object {
    ObjectName name;
    std::vector<Attribute> attributes;  // in the template's order
    // The attribute labelled so; nullptr when the template has none or it is absent.
    const Attribute* attribute(std::string_view label) const;
};

// One explicitly formatted logical record: a set of objects of one type.
struct Set {
    std::string type;    // "CHANNEL", "FRAME", "PARAMETER", "ORIGIN", ...
    std::string name;    // often empty
    int recordType = 0;  // the logical record type (0 FHLR, 1 OLR, 3 CHANNL, 4 FRAME, 5 STATIC ...)
    std::size_t offset = 0;    // byte offset of the record's first segment in the file
    bool redundant = false;    // a redundant set (RDSET): a copy of an earlier one
    bool replacement = false;  // a replacement set (RSET): updates objects of an earlier one
    std::vector<Attribute> templ;
    std::vector<Object> objects;
};

// A channel as its CHANNEL object describes it.
struct Channel {
    ObjectName name;
    std::string longName;
    std::string units;
    int repCode = kFDOUBL;                 // default when the object does not say
    std::vector<std::uint32_t> dimension;  // {1} for a scalar, {40} for a 40-finger array
    std::size_t elements() const;          // the product of the dimension (1 for none)
};

// A frame: the channels sampled together, its first channel the index.
struct Frame {
    ObjectName name;
    std::string indexType;  // "BOREHOLE-DEPTH", "TIME", ... ("" when the frame does not say)
    std::string direction;  // "INCREASING", "DECREASING" or ""
    std::vector<std::size_t> channels;  // into LogicalFile::channels, in frame order
    std::size_t frameBytes = 0;         // bytes of one frame's values; 0 when variable
    std::size_t records = 0;            // frame data records (FDATA) that name it
};

struct Parameter {
    ObjectName name;
    std::string longName;
    std::string units;  // of the VALUES attribute
    std::vector<std::uint32_t> dimension;
    std::vector<Value> values;
};

// One logical file: from a FILE-HEADER record to the next.
struct LogicalFile {
    std::string id;          // the FILE-HEADER's ID
    std::size_t offset = 0;  // byte offset of the file header
    std::vector<Set> sets;   // every set, in file order
    // From the first ORIGIN object ("" where it does not say).
    std::string wellName, wellId, fieldName, company, producer, product, creationTime;
    std::vector<Channel> channels;
    std::vector<Frame> frames;
    std::vector<Parameter> parameters;
    std::size_t frameRecords = 0;  // FDATA records of every frame
    std::size_t otherRecords = 0;  // indirectly formatted records not frame data (NOFORMAT, EOD)
    std::size_t encryptedRecords = 0;     // skipped: encrypted
    std::size_t unknownFrameRecords = 0;  // FDATA naming a frame the file does not define

    // The set objects of `type` (in file order), or nullptr.
    const Channel* channel(const ObjectName& name) const;
    std::vector<const Object*> objects(std::string_view type) const;
};

// What indexing a DLIS file finds: the storage unit label and every logical file's
// explicitly formatted records (frame data are counted, not decoded).
struct DlisIndex {
    std::size_t sulOffset = 0;        // bytes before the storage unit label (leading garbage)
    bool hasSul = true;               // false when the file starts with a visible record
    std::string version;              // "V1.00"
    std::string structure;            // "RECORD"
    std::size_t maxRecordLength = 0;  // from the label (0: unlimited)
    std::string storageSetId;         // the label's storage set identifier
    bool tapeImage = false;           // wrapped in tape-image marks (12-byte little endian)
    std::vector<LogicalFile> files;
};

}  // namespace caliper3d::io::dlis

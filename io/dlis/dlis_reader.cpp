#include "io/dlis/dlis_reader.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "io/dlis/dlis_cursor.h"
#include "io/dlis/dlis_records.h"
#include "io/parse_error.h"

namespace caliper3d::io::dlis {

namespace {

// Component roles (RP66 v1 3.2.2.1): the top three bits of a component's descriptor.
enum Role : int {
    kAbsentAttribute = 0,
    kAttribute = 1,
    kInvariantAttribute = 2,
    kObject = 3,
    kRedundantSet = 5,
    kReplacementSet = 6,
    kSet = 7
};

constexpr int kFileHeader = 0;  // logical record type of a FILE-HEADER set
constexpr int kFrameData = 0;   // indirectly formatted: FDATA
constexpr std::size_t kMaxElements = 1u << 20;

int roleOf(std::uint8_t descriptor) {
    return descriptor >> 5;
}

// Reads an attribute component whose descriptor is `descriptor`; what it leaves out is
// taken from `defaults` (the template's attribute, or the standard's defaults).
Attribute readAttribute(Cursor& c, std::uint8_t descriptor, const Attribute& defaults,
                        bool inObject = false) {
    Attribute a = defaults;
    a.absent = false;
    a.invariant = !inObject && roleOf(descriptor) == kInvariantAttribute;
    // An object's attributes have no label (RP66 v1 3.2.2.2): a set label flag is ignored.
    if ((descriptor & 0x10) && !inObject) a.label = c.ident();
    const bool countGiven = (descriptor & 0x08) != 0, codeGiven = (descriptor & 0x04) != 0;
    if (countGiven) a.count = c.uvari();
    if (codeGiven) a.repCode = c.ushort();
    if (descriptor & 0x02) a.units = c.ident();
    if (descriptor & 0x01) {
        // Every value takes a byte at least: a count beyond the body is damage, not memory.
        if (a.count > c.remaining())
            throw BodyError(c.position(), "attribute " + a.label + " declares " +
                                              std::to_string(a.count) + " values in " +
                                              std::to_string(c.remaining()) + " bytes");
        a.values.clear();
        a.values.reserve(a.count);
        for (std::uint32_t i = 0; i < a.count; ++i) a.values.push_back(c.value(a.repCode));
    } else if (countGiven || codeGiven) {
        // The template's value does not fit a new count or code: no value.
        if (a.count != defaults.count || a.repCode != defaults.repCode) a.values.clear();
    }
    return a;
}

Set readSet(const LogicalRecord& record, std::vector<std::string>& notes) {
    Cursor c(record.body, record.size);
    Set set;
    set.recordType = record.type;
    set.offset = record.offset;
    const std::uint8_t head = c.ushort();
    const int role = roleOf(head);
    if (role != kSet && role != kReplacementSet && role != kRedundantSet)
        throw BodyError(
            0, "expected a set component, found a component of role " + std::to_string(role));
    set.redundant = role == kRedundantSet;
    set.replacement = role == kReplacementSet;
    // The type is mandatory: a set without its flag still holds it.
    if (!(head & 0x10)) notes.emplace_back("set type flag not set; type read anyway");
    set.type = c.ident();
    if (head & 0x08) set.name = c.ident();
    // The template: attribute components up to the first object.
    while (!c.atEnd() && roleOf(c.peek()) != kObject) {
        const std::uint8_t d = c.ushort();
        const int r = roleOf(d);
        if (r == kAbsentAttribute) {
            notes.push_back("absent attribute in the template of " + set.type + "; ignored");
            continue;
        }
        if (r != kAttribute && r != kInvariantAttribute)
            throw BodyError(c.position() - 1,
                            "expected an attribute in the set's template, found "
                            "a component of role " +
                                std::to_string(r));
        set.templ.push_back(readAttribute(c, d, Attribute{}));
    }
    while (!c.atEnd()) {
        const std::uint8_t d = c.ushort();
        if (roleOf(d) != kObject)
            throw BodyError(c.position() - 1, "expected an object, found a component of role " +
                                                  std::to_string(roleOf(d)));
        Object object;
        if (!(d & 0x10)) notes.emplace_back("object name flag not set; name read anyway");
        object.name = c.obname();
        for (const Attribute& t : set.templ) {
            if (t.invariant) {
                object.attributes.push_back(t);
                continue;
            }
            if (c.atEnd() || roleOf(c.peek()) == kObject) {
                object.attributes.push_back(t);
                continue;
            }
            const std::uint8_t ad = c.ushort();
            const int r = roleOf(ad);
            if (r == kAbsentAttribute) {
                Attribute absent;
                absent.label = t.label;
                absent.absent = true;
                object.attributes.push_back(absent);
            } else if (r == kAttribute || r == kInvariantAttribute) {
                if (r == kInvariantAttribute || (ad & 0x10))
                    notes.push_back("attribute " + t.label + " of object " + object.name.id +
                                    " has an invariant or label flag; read as an attribute");
                Attribute a = readAttribute(c, ad, t, true);
                a.label = t.label;
                object.attributes.push_back(std::move(a));
            } else {
                throw BodyError(c.position() - 1, "expected an attribute of object " +
                                                      object.name.id + ", found role " +
                                                      std::to_string(r));
            }
        }
        if (!c.atEnd() && roleOf(c.peek()) != kObject)
            throw BodyError(c.position(), "object " + object.name.id +
                                              " holds more attributes than the template");
        set.objects.push_back(std::move(object));
    }
    return set;
}

std::string textOf(const Object& o, std::string_view label) {
    const Attribute* a = o.attribute(label);
    return a ? a->text() : std::string();
}

std::vector<std::uint32_t> dimensionOf(const Object& o) {
    std::vector<std::uint32_t> out;
    if (const Attribute* a = o.attribute("DIMENSION"))
        for (std::size_t i = 0; i < a->values.size(); ++i) {
            const double v = a->number(i);
            if (std::isfinite(v) && v >= 0 && v <= static_cast<double>(kMaxElements))
                out.push_back(static_cast<std::uint32_t>(v));
        }
    if (out.empty()) out.push_back(1);
    return out;
}

// Channels, frames, parameters and the origin from the sets read.
void describeFile(LogicalFile& file, const std::string& name, Diagnostics* diagnostics) {
    for (const Object* o : file.objects("ORIGIN")) {
        file.wellName = textOf(*o, "WELL-NAME");
        file.wellId = textOf(*o, "WELL-ID");
        file.fieldName = textOf(*o, "FIELD-NAME");
        file.company = textOf(*o, "COMPANY");
        file.producer = textOf(*o, "PRODUCER-NAME");
        file.product = textOf(*o, "PRODUCT");
        file.creationTime = textOf(*o, "CREATION-TIME");
        break;
    }
    for (const Object* o : file.objects("CHANNEL")) {
        Channel ch;
        ch.name = o->name;
        ch.longName = textOf(*o, "LONG-NAME");
        ch.units = textOf(*o, "UNITS");
        if (const Attribute* a = o->attribute("REPRESENTATION-CODE"); a && !a->values.empty()) {
            const double code = a->number();
            if (std::isfinite(code) && code >= 1 && code <= 27 && code == std::floor(code)) {
                ch.repCode = static_cast<int>(code);
            } else {
                // Not a code RP66 defines (1..27): the channel's values cannot be read.
                ch.repCode = 0;
                if (diagnostics)
                    diagnostics->warn(name, 0,
                                      "channel " + ch.name.id + " gives representation code " +
                                          a->text() +
                                          ", which RP66 does not define (1 to 27); "
                                          "its values are not read");
            }
        }
        ch.dimension = dimensionOf(*o);
        std::size_t elements = 1;
        for (std::uint32_t d : ch.dimension) elements = std::min(elements * d, kMaxElements);
        if (elements >= kMaxElements) ch.dimension = {0};
        file.channels.push_back(std::move(ch));
    }
    for (const Object* o : file.objects("FRAME")) {
        Frame f;
        f.name = o->name;
        f.indexType = textOf(*o, "INDEX-TYPE");
        f.direction = textOf(*o, "DIRECTION");
        bool fixed = true;
        if (const Attribute* a = o->attribute("CHANNELS"))
            for (const Value& v : a->values) {
                const ObjectName* n = std::get_if<ObjectName>(&v);
                if (!n) continue;
                std::size_t k = 0;
                while (k < file.channels.size() && file.channels[k].name != *n) ++k;
                if (k == file.channels.size()) {
                    if (diagnostics)
                        diagnostics->warn(name, 0,
                                          "frame " + f.name.id + " names channel " + n->id +
                                              ", which the file does not define; "
                                              "the frame cannot be read");
                    f.channels.clear();
                    fixed = false;
                    break;
                }
                f.channels.push_back(k);
                const Channel& ch = file.channels[k];
                const std::size_t size = repCodeSize(ch.repCode);
                if (size == 0) fixed = false;
                f.frameBytes += size * ch.elements();
            }
        if (!fixed) f.frameBytes = 0;
        file.frames.push_back(std::move(f));
    }
    for (const Object* o : file.objects("PARAMETER")) {
        Parameter p;
        p.name = o->name;
        p.longName = textOf(*o, "LONG-NAME");
        p.dimension = dimensionOf(*o);
        if (const Attribute* a = o->attribute("VALUES")) {
            p.units = a->units;
            p.values = a->values;
        }
        file.parameters.push_back(std::move(p));
    }
}

[[noreturn]] void refuse(const std::string& name, std::size_t offset, const std::string& what) {
    throw ParseError(name, 0, 0, "byte " + std::to_string(offset) + ": " + what);
}

}  // namespace

namespace {

using FrameCounts = std::vector<std::pair<ObjectName, std::size_t>>;

void countFrameRecord(const LogicalRecord& record, LogicalFile& file, FrameCounts& counts) {
    if (record.type != kFrameData || record.size == 0) {
        ++file.otherRecords;
        return;
    }
    ObjectName frame;
    try {
        Cursor c(record.body, record.size);
        frame = c.obname();
    } catch (const BodyError&) {
        ++file.unknownFrameRecords;
        return;
    }
    ++file.frameRecords;
    for (auto& [n, count] : counts)
        if (n == frame) {
            ++count;
            return;
        }
    counts.emplace_back(frame, 1);
}

void readEflr(const LogicalRecord& record, LogicalFile& file, const std::string& name,
              Diagnostics* diagnostics) {
    std::vector<std::string> notes;
    try {
        file.sets.push_back(readSet(record, notes));
        if (diagnostics)
            for (const std::string& n : notes)
                diagnostics->warn(name, 0, "byte " + std::to_string(record.offset) + ": " + n);
        if (file.sets.back().type == "FILE-HEADER")
            for (const Object& o : file.sets.back().objects)
                if (const Attribute* id = o.attribute("ID")) file.id = id->text();
    } catch (const BodyError& e) {
        if (diagnostics)
            diagnostics->warn(name, 0,
                              "byte " + std::to_string(record.offset) + ": set skipped (byte " +
                                  std::to_string(e.at) + " of the record): " + e.what());
    }
}

}  // namespace

DlisIndex indexDlis(std::string_view bytes, const std::string& name, Diagnostics* diagnostics) {
    std::optional<RecordStream> stream;
    try {
        stream.emplace(bytes, name, diagnostics);
    } catch (const EnvelopeError& e) {
        refuse(name, e.offset, e.what());
    }
    DlisIndex index = stream->label;
    std::vector<FrameCounts> counts;
    LogicalRecord record;
    try {
        while (stream->next(record)) {
            const bool header =
                record.explicitlyFormatted && record.type == kFileHeader && !record.encrypted;
            if (header || index.files.empty()) {
                if (!header && diagnostics)
                    diagnostics->warn(name, 0,
                                      "byte " + std::to_string(record.offset) +
                                          ": records before any FILE-HEADER; read as a "
                                          "logical file of their own");
                index.files.emplace_back();
                index.files.back().offset = record.offset;
                counts.emplace_back();
            }
            LogicalFile& file = index.files.back();
            if (record.encrypted)
                ++file.encryptedRecords;
            else if (!record.explicitlyFormatted)
                countFrameRecord(record, file, counts.back());
            else
                readEflr(record, file, name, diagnostics);
        }
    } catch (const EnvelopeError& e) {
        if (index.files.empty()) refuse(name, e.offset, e.what());
        if (diagnostics)
            diagnostics->warn(name, 0,
                              "byte " + std::to_string(e.offset) + ": " + e.what() +
                                  "; what follows is not read");
    }
    if (index.files.empty())
        refuse(name, bytes.size(), "expected logical records, found the end of the file");
    for (std::size_t i = 0; i < index.files.size(); ++i) {
        LogicalFile& f = index.files[i];
        describeFile(f, name, diagnostics);
        std::size_t matched = 0;
        for (Frame& frame : f.frames)
            for (const auto& [n, count] : counts[i])
                if (n == frame.name) {
                    frame.records = count;
                    matched += count;
                }
        f.unknownFrameRecords += f.frameRecords - std::min(matched, f.frameRecords);
        if (f.encryptedRecords && diagnostics)
            diagnostics->warn(
                name, 0,
                "byte " + std::to_string(f.offset) + ": " + std::to_string(f.encryptedRecords) +
                    (f.encryptedRecords == 1 ? " encrypted record" : " encrypted records") +
                    " skipped in logical file " + std::to_string(i + 1));
    }
    return index;
}

FrameRead frameRead(const LogicalFile& file, const Frame& frame,
                    std::vector<std::size_t> channels) {
    FrameRead read;
    read.channels = std::move(channels);
    for (std::size_t k : read.channels)
        if (k < frame.channels.size()) read.width += file.channels[frame.channels[k]].elements();
    return read;
}

namespace {

// How one channel of a frame is laid out and where its wanted values go.
struct ChannelSlot {
    int code = kFDOUBL;
    std::size_t elements = 1;
    std::size_t size = 0;        // bytes per value; 0: variable
    std::ptrdiff_t output = -1;  // first output element; -1: not wanted
};

// Decodes one frame's values after its name and number; false when the record holds less
// than a whole frame.
bool decodeFrame(Cursor& c, const std::vector<ChannelSlot>& slots, double* out) {
    for (const ChannelSlot& s : slots) {
        if (s.size && s.output < 0) {
            if (s.size * s.elements > c.remaining()) return false;
            c.skip(s.size * s.elements);
            continue;
        }
        for (std::size_t e = 0; e < s.elements; ++e) {
            if (s.size) {
                if (s.size > c.remaining()) return false;
                const double v = decodeNumber(s.code, c.here());
                c.skip(s.size);
                if (s.output >= 0) out[static_cast<std::size_t>(s.output) + e] = v;
            } else {
                const Value v = c.value(s.code);
                if (s.output < 0) continue;
                const double* d = std::get_if<double>(&v);
                out[static_cast<std::size_t>(s.output) + e] =
                    d ? *d : std::numeric_limits<double>::quiet_NaN();
            }
        }
    }
    return true;
}

}  // namespace

void readFrames(std::string_view bytes, const std::string& name, const DlisIndex& index,
                std::size_t fileIndex, std::size_t frameIndex, const FrameRead& wanted,
                const FrameConsumer& consumer, Diagnostics* diagnostics) {
    const LogicalFile& file = index.files.at(fileIndex);
    const Frame& frame = file.frames.at(frameIndex);
    std::vector<ChannelSlot> slots(frame.channels.size());
    for (std::size_t k = 0; k < frame.channels.size(); ++k) {
        const Channel& ch = file.channels[frame.channels[k]];
        slots[k].code = ch.repCode;
        slots[k].elements = ch.elements();
        slots[k].size = repCodeSize(ch.repCode);
    }
    std::size_t at = 0;
    for (std::size_t k : wanted.channels) {
        if (k >= slots.size()) continue;
        slots[k].output = static_cast<std::ptrdiff_t>(at);
        at += slots[k].elements;
    }
    std::vector<double> values(std::max<std::size_t>(at, 1));
    RecordStream stream(bytes, name, nullptr);
    LogicalRecord record;
    std::size_t fileNumber = 0, shortRecords = 0, firstShort = 0;
    try {
        while (stream.next(record)) {
            if (record.explicitlyFormatted && record.type == kFileHeader && !record.encrypted)
                ++fileNumber;
            if (fileNumber == 0) fileNumber = 1;  // records before any header: file 1
            if (fileNumber - 1 < fileIndex) continue;
            if (fileNumber - 1 > fileIndex) break;
            if (record.explicitlyFormatted || record.encrypted || record.type != kFrameData)
                continue;
            Cursor c(record.body, record.size);
            try {
                if (c.obname() != frame.name) continue;
            } catch (const BodyError&) {
                if (shortRecords++ == 0) firstShort = record.offset;  // its name cut short
                continue;
            }
            // A record may hold several frames, each its number and its values.
            bool whole = true, stop = false;
            do {
                std::uint32_t number = 0;
                try {
                    number = c.uvari();
                    std::fill(values.begin(), values.end(),
                              std::numeric_limits<double>::quiet_NaN());
                    whole = decodeFrame(c, slots, values.data());
                } catch (const BodyError&) {
                    whole = false;
                }
                if (!whole) break;
                if (!consumer(number, values.data(), record.offset)) stop = true;
            } while (!stop && !c.atEnd());
            if (!whole && shortRecords++ == 0) firstShort = record.offset;
            if (stop) break;
        }
    } catch (const EnvelopeError& e) {
        if (diagnostics)
            diagnostics->warn(name, 0,
                              "byte " + std::to_string(e.offset) + ": " + e.what() +
                                  "; the frames after it are not read");
    }
    if (shortRecords && diagnostics)
        diagnostics->warn(name, 0,
                          "byte " + std::to_string(firstShort) + ": " +
                              std::to_string(shortRecords) + " frame records of " + frame.name.id +
                              " hold less than a whole frame; skipped");
}

}  // namespace caliper3d::io::dlis

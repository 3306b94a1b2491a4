#include "support/dlis_writer.h"

#include "io/atomic_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace caliper3d::test::dlis {

namespace {

void putBytes(std::string& out, std::uint64_t value, int bytes) {
    for (int i = bytes - 1; i >= 0; --i)
        out.push_back(static_cast<char>((value >> (8 * i)) & 0xFFu));
}

std::uint32_t floatBits(float f) {
    std::uint32_t u = 0;
    std::memcpy(&u, &f, sizeof u);
    return u;
}

std::uint64_t doubleBits(double d) {
    std::uint64_t u = 0;
    std::memcpy(&u, &d, sizeof u);
    return u;
}

// FSHORT: a 12-bit two's complement fraction M/2048 and a 4-bit exponent E, M/2048 * 2^E.
std::uint16_t fshort(double v) {
    for (int e = 0; e < 16; ++e) {
        const double m = std::round(v / std::ldexp(1.0, e) * 2048.0);
        if (m >= -2048.0 && m <= 2047.0) {
            const auto bits = static_cast<std::uint16_t>(static_cast<int>(m) & 0x0FFF);
            return static_cast<std::uint16_t>((bits << 4) | e);
        }
    }
    throw std::invalid_argument("FSHORT cannot hold " + std::to_string(v));
}

// ISINGL (IBM System/360 single): sign, excess-64 base-16 exponent, 24-bit fraction in
// [1/16, 1).
std::uint32_t isingl(double v) {
    if (v == 0.0) return 0;
    const std::uint32_t sign = v < 0 ? 0x80000000u : 0u;
    double x = std::abs(v);
    int e = 0;
    while (x >= 1.0) {
        x /= 16.0;
        ++e;
    }
    while (x < 1.0 / 16.0) {
        x *= 16.0;
        --e;
    }
    auto f = static_cast<std::uint32_t>(std::llround(x * 16777216.0));
    if (f >= 16777216u) {
        f >>= 4;
        ++e;
    }
    return sign | (static_cast<std::uint32_t>(e + 64) << 24) | f;
}

// VSINGL (VAX F): sign, excess-128 exponent, 0.1fff... with a hidden bit; written as two
// little-endian 16-bit words, the high word first.
std::uint32_t vsinglWord(double v) {
    if (v == 0.0) return 0;
    const std::uint32_t sign = v < 0 ? 0x80000000u : 0u;
    int e = 0;
    const double f = std::frexp(std::abs(v), &e);  // f in [0.5, 1)
    auto m = static_cast<std::uint32_t>(std::llround(f * 16777216.0));
    if (m >= 16777216u) {
        m >>= 1;
        ++e;
    }
    return sign | (static_cast<std::uint32_t>(e + 128) << 23) | (m & 0x7FFFFFu);
}

int timeZone(const std::string& text) {
    if (text.find("GMT") != std::string::npos) return 2;
    if (text.find("daylight") != std::string::npos) return 1;
    return 0;
}

}  // namespace

int components(int code) {
    switch (code) {
        case FSING1:
        case FDOUB1:
        case CSINGL:
        case CDOUBL:
            return 2;
        case FSING2:
        case FDOUB2:
            return 3;
        default:
            return 1;
    }
}

void putUvari(std::string& out, std::uint32_t value, int width) {
    if (width == 0) width = value < 0x80u ? 1 : value < 0x4000u ? 2 : 4;
    if (width == 1 && value < 0x80u)
        putBytes(out, value, 1);
    else if (width == 2 && value < 0x4000u)
        putBytes(out, 0x8000u | value, 2);
    else if (value < 0x40000000u)
        putBytes(out, 0xC0000000u | value, 4);
    else
        throw std::invalid_argument("UVARI cannot hold " + std::to_string(value));
}

void putNumber(std::string& out, int code, double v) {
    auto integer = [&](double lo, double hi) {
        const double r = std::round(v);
        if (!(r >= lo && r <= hi))
            throw std::invalid_argument("code " + std::to_string(code) + " cannot hold " +
                                        std::to_string(v));
        return static_cast<std::int64_t>(r);
    };
    switch (code) {
        case FSHORT:
            putBytes(out, fshort(v), 2);
            return;
        case FSINGL:
        case FSING1:
        case FSING2:
        case CSINGL:
            putBytes(out, floatBits(static_cast<float>(v)), 4);
            return;
        case ISINGL:
            putBytes(out, isingl(v), 4);
            return;
        case VSINGL: {
            const std::uint32_t w = vsinglWord(v);
            out.push_back(static_cast<char>((w >> 16) & 0xFFu));
            out.push_back(static_cast<char>((w >> 24) & 0xFFu));
            out.push_back(static_cast<char>(w & 0xFFu));
            out.push_back(static_cast<char>((w >> 8) & 0xFFu));
            return;
        }
        case FDOUBL:
        case FDOUB1:
        case FDOUB2:
        case CDOUBL:
            putBytes(out, doubleBits(v), 8);
            return;
        case SSHORT:
            putBytes(out, static_cast<std::uint64_t>(integer(-128, 127)) & 0xFFu, 1);
            return;
        case SNORM:
            putBytes(out, static_cast<std::uint64_t>(integer(-32768, 32767)) & 0xFFFFu, 2);
            return;
        case SLONG:
            putBytes(out, static_cast<std::uint64_t>(integer(-2147483648.0, 2147483647.0)), 4);
            return;
        case USHORT:
        case STATUS:
            putBytes(out, static_cast<std::uint64_t>(integer(0, 255)), 1);
            return;
        case UNORM:
            putBytes(out, static_cast<std::uint64_t>(integer(0, 65535)), 2);
            return;
        case ULONG:
            putBytes(out, static_cast<std::uint64_t>(integer(0, 4294967295.0)), 4);
            return;
        case UVARI:
        case ORIGIN:
            putUvari(out, static_cast<std::uint32_t>(integer(0, 1073741823.0)));
            return;
        default:
            throw std::invalid_argument("code " + std::to_string(code) + " is not a number");
    }
}

void putIdent(std::string& out, const std::string& text) {
    if (text.size() > 255) throw std::invalid_argument("IDENT longer than 255: " + text);
    putBytes(out, text.size(), 1);
    out += text;
}

void putAscii(std::string& out, const std::string& text) {
    putUvari(out, static_cast<std::uint32_t>(text.size()));
    out += text;
}

void putDtime(std::string& out, const std::string& text) {
    int y = 0, mo = 0, d = 0, h = 0, mi = 0, s = 0, ms = 0;
    if (std::sscanf(text.c_str(), "%d-%d-%d %d:%d:%d.%d", &y, &mo, &d, &h, &mi, &s, &ms) < 6)
        throw std::invalid_argument("DTIME needs YYYY-MM-DD hh:mm:ss: " + text);
    putBytes(out, static_cast<std::uint64_t>(y - 1900), 1);
    putBytes(out, static_cast<std::uint64_t>((timeZone(text) << 4) | mo), 1);
    putBytes(out, static_cast<std::uint64_t>(d), 1);
    putBytes(out, static_cast<std::uint64_t>(h), 1);
    putBytes(out, static_cast<std::uint64_t>(mi), 1);
    putBytes(out, static_cast<std::uint64_t>(s), 1);
    putBytes(out, static_cast<std::uint64_t>(ms), 2);
}

void putObname(std::string& out, const Name& name) {
    putUvari(out, name.origin);
    putBytes(out, name.copy, 1);
    putIdent(out, name.id);
}

std::uint32_t Values::count() const {
    if (!names.empty()) return static_cast<std::uint32_t>(names.size());
    if (!texts.empty()) return static_cast<std::uint32_t>(texts.size());
    return static_cast<std::uint32_t>(numbers.size() / static_cast<std::size_t>(components(code)));
}

Values numbers(int code, std::vector<double> values) {
    Values v;
    v.code = code;
    v.numbers = std::move(values);
    return v;
}

Values texts(int code, std::vector<std::string> values) {
    Values v;
    v.code = code;
    v.texts = std::move(values);
    return v;
}

Values names(std::vector<Name> values) {
    Values v;
    v.code = OBNAME;
    v.names = std::move(values);
    return v;
}

Attr attr(const std::string& label, Values values, const std::string& units) {
    Attr a;
    a.label = label;
    a.values = std::move(values);
    a.units = units;
    a.writeUnits = !units.empty();
    a.writeValue = a.values.count() > 0;
    a.writeCount = a.values.count() != 1 || !a.writeValue;
    if (!a.writeValue) a.writeCount = false;
    return a;
}

Attr fromTemplate() {
    Attr a;
    a.writeLabel = a.writeCount = a.writeCode = a.writeUnits = a.writeValue = false;
    return a;
}

Attr valueOnly(Values values) {
    Attr a = fromTemplate();
    a.values = std::move(values);
    a.writeValue = true;
    return a;
}

Attr absentAttr() {
    Attr a = fromTemplate();
    a.absent = true;
    return a;
}

namespace {

void putValues(std::string& out, const Values& v) {
    switch (v.code) {
        case IDENT:
        case UNITS:
            for (const std::string& t : v.texts) putIdent(out, t);
            return;
        case ASCII:
            for (const std::string& t : v.texts) putAscii(out, t);
            return;
        case DTIME:
            for (const std::string& t : v.texts) putDtime(out, t);
            return;
        case OBNAME:
            for (const Name& n : v.names) putObname(out, n);
            return;
        default:
            for (double x : v.numbers) putNumber(out, v.code, x);
            return;
    }
}

void putAttr(std::string& out, const Attr& a, bool inTemplate) {
    if (a.absent) {
        out.push_back(0x00);
        return;
    }
    const bool label = inTemplate && a.writeLabel && !a.label.empty();
    unsigned char d = 0x20;
    if (label) d |= 0x10;
    if (a.writeCount) d |= 0x08;
    if (a.writeCode) d |= 0x04;
    if (a.writeUnits) d |= 0x02;
    if (a.writeValue) d |= 0x01;
    out.push_back(static_cast<char>(d));
    if (label) putIdent(out, a.label);
    if (a.writeCount) putUvari(out, a.values.count());
    if (a.writeCode) putBytes(out, static_cast<std::uint64_t>(a.values.code), 1);
    if (a.writeUnits) putIdent(out, a.units);
    if (a.writeValue) putValues(out, a.values);
}

}  // namespace

std::string encodeSet(const Set& set) {
    std::string out;
    const unsigned char role = set.role == Set::Replacement ? 0xC0
                               : set.role == Set::Redundant ? 0xA0
                                                            : 0xE0;
    out.push_back(static_cast<char>(role | 0x10 | (set.name.empty() ? 0 : 0x08)));
    putIdent(out, set.type);
    if (!set.name.empty()) putIdent(out, set.name);
    for (const Attr& a : set.templ) putAttr(out, a, true);
    for (const Object& o : set.objects) {
        out.push_back(0x70);
        putObname(out, o.name);
        for (const Attr& a : o.attrs) putAttr(out, a, false);
    }
    return out;
}

std::size_t ChannelSpec::elements() const {
    std::size_t n = 1;
    for (std::uint32_t d : dimension) n *= d;
    return n;
}

std::size_t FrameSpec::width() const {
    std::size_t n = 0;
    for (const ChannelSpec& c : channels) n += c.elements();
    return n;
}

void FrameSpec::addRow(const std::vector<double>& row) {
    if (row.size() != width())
        throw std::invalid_argument("frame row of " + std::to_string(row.size()) +
                                    " values, expected " + std::to_string(width()));
    values.insert(values.end(), row.begin(), row.end());
}

namespace {

Record eflr(int type, const Set& set) {
    return {true, type, encodeSet(set), false};
}

Set fileHeader(const LogicalFileSpec& f, std::size_t sequence) {
    Set s;
    s.type = "FILE-HEADER";
    s.templ = {attr("SEQUENCE-NUMBER", texts(ASCII, {})), attr("ID", texts(ASCII, {}))};
    std::string seq = std::to_string(sequence);
    seq.insert(0, 10 - std::min<std::size_t>(10, seq.size()), ' ');
    std::string id = f.fileId;
    id.resize(std::max<std::size_t>(65, id.size()), ' ');
    s.objects.push_back(
        {{f.origin, 0, "0"}, {valueOnly(texts(ASCII, {seq})), valueOnly(texts(ASCII, {id}))}});
    return s;
}

Set originSet(const LogicalFileSpec& f) {
    Set s;
    s.type = "ORIGIN";
    s.templ = {
        attr("FILE-ID", texts(ASCII, {})),           attr("FILE-SET-NAME", texts(IDENT, {})),
        attr("FILE-SET-NUMBER", numbers(UVARI, {})), attr("FILE-NUMBER", numbers(UVARI, {})),
        attr("FILE-TYPE", texts(IDENT, {})),         attr("PRODUCT", texts(ASCII, {})),
        attr("VERSION", texts(ASCII, {})),           attr("PROGRAMS", texts(ASCII, {})),
        attr("CREATION-TIME", texts(DTIME, {})),     attr("ORDER-NUMBER", texts(ASCII, {})),
        attr("DESCENT-NUMBER", numbers(UNORM, {})),  attr("RUN-NUMBER", numbers(UVARI, {})),
        attr("WELL-ID", texts(ASCII, {})),           attr("WELL-NAME", texts(ASCII, {})),
        attr("FIELD-NAME", texts(ASCII, {})),        attr("PRODUCER-CODE", numbers(UNORM, {})),
        attr("PRODUCER-NAME", texts(ASCII, {})),     attr("COMPANY", texts(ASCII, {}))};
    auto text = [](int code, const std::string& t) {
        return t.empty() ? absentAttr() : attr("", texts(code, {t}));
    };
    Object o;
    o.name = {f.origin, 0, "DLIS_DEFINING_ORIGIN"};
    o.attrs = {text(ASCII, f.fileId),
               text(IDENT, "CALIPER3D"),
               attr("", numbers(UVARI, {static_cast<double>(f.origin)})),
               attr("", numbers(UVARI, {static_cast<double>(f.runNumber)})),
               text(IDENT, "TEST"),
               text(ASCII, f.product),
               absentAttr(),
               absentAttr(),
               text(DTIME, f.creationTime),
               absentAttr(),
               absentAttr(),
               attr("", numbers(UVARI, {static_cast<double>(f.runNumber)})),
               text(ASCII, f.wellId),
               text(ASCII, f.wellName),
               text(ASCII, f.fieldName),
               attr("", numbers(UNORM, {440})),
               text(ASCII, f.producerName),
               text(ASCII, f.company)};
    s.objects.push_back(std::move(o));
    return s;
}

// PARAMETER set: LONG-NAME, DIMENSION (template default 1), AXIS, ZONES (absent), VALUES.
Set parameterSet(const LogicalFileSpec& f) {
    Set s;
    s.type = "PARAMETER";
    s.templ = {attr("LONG-NAME", texts(ASCII, {})), attr("DIMENSION", numbers(UVARI, {1})),
               attr("AXIS", names({})), attr("ZONES", names({})),
               attr("VALUES", numbers(FDOUBL, {}))};
    for (const ParameterSpec& p : f.parameters) {
        Object o;
        o.name = {f.origin, 0, p.name};
        o.attrs.push_back(p.longName.empty() ? absentAttr()
                                             : valueOnly(texts(ASCII, {p.longName})));
        const bool text = p.numbers.empty();
        const std::size_t n =
            text ? p.texts.size() : p.numbers.size() / static_cast<std::size_t>(components(p.code));
        o.attrs.push_back(n == 1 ? fromTemplate()
                                 : attr("", numbers(UVARI, {static_cast<double>(n)})));
        o.attrs.push_back(absentAttr());
        o.attrs.push_back(absentAttr());
        o.attrs.push_back(text ? attr("", texts(ASCII, p.texts), p.units)
                               : attr("", numbers(p.code, p.numbers), p.units));
        s.objects.push_back(std::move(o));
    }
    return s;
}

// CHANNEL set: LONG-NAME, PROPERTIES (absent), REPRESENTATION-CODE (template default
// FSINGL), UNITS, DIMENSION (template default 1), ELEMENT-LIMIT; a scalar FSINGL channel
// takes both defaults.
Set channelSet(const LogicalFileSpec& f) {
    Set s;
    s.type = "CHANNEL";
    s.templ = {attr("LONG-NAME", texts(ASCII, {})),
               attr("PROPERTIES", texts(IDENT, {})),
               attr("REPRESENTATION-CODE", numbers(USHORT, {FSINGL})),
               attr("UNITS", texts(UNITS, {})),
               attr("DIMENSION", numbers(UVARI, {1})),
               attr("ELEMENT-LIMIT", numbers(UVARI, {1}))};
    for (const FrameSpec& frame : f.frames)
        for (const ChannelSpec& c : frame.channels) {
            Object o;
            o.name = {f.origin, 0, c.name};
            o.attrs.push_back(c.longName.empty() ? absentAttr()
                                                 : valueOnly(texts(ASCII, {c.longName})));
            o.attrs.push_back(absentAttr());
            o.attrs.push_back(c.code == FSINGL ? fromTemplate()
                                               : valueOnly(numbers(USHORT, {double(c.code)})));
            o.attrs.push_back(c.units.empty() ? absentAttr() : valueOnly(texts(UNITS, {c.units})));
            const bool scalar = c.dimension.size() == 1 && c.dimension[0] == 1;
            if (!scalar) {
                std::vector<double> d(c.dimension.begin(), c.dimension.end());
                o.attrs.push_back(attr("", numbers(UVARI, d)));
                o.attrs.push_back(attr("", numbers(UVARI, d)));
            }  // else DIMENSION and ELEMENT-LIMIT left to the template (object ends early)
            s.objects.push_back(std::move(o));
        }
    return s;
}

// FRAME set: DESCRIPTION (absent), CHANNELS, INDEX-TYPE, DIRECTION, SPACING, INDEX-MIN,
// INDEX-MAX.
Set frameSet(const LogicalFileSpec& f) {
    Set s;
    s.type = "FRAME";
    s.templ = {attr("DESCRIPTION", texts(ASCII, {})),  attr("CHANNELS", names({})),
               attr("INDEX-TYPE", texts(IDENT, {})),   attr("DIRECTION", texts(IDENT, {})),
               attr("SPACING", numbers(FDOUBL, {})),   attr("ENCRYPTED", numbers(USHORT, {})),
               attr("INDEX-MIN", numbers(FDOUBL, {})), attr("INDEX-MAX", numbers(FDOUBL, {}))};
    for (const FrameSpec& frame : f.frames) {
        Object o;
        o.name = {f.origin, 0, frame.name};
        std::vector<Name> channels;
        for (const ChannelSpec& c : frame.channels) channels.push_back({f.origin, 0, c.name});
        o.attrs.push_back(absentAttr());
        o.attrs.push_back(attr("", names(channels)));
        o.attrs.push_back(frame.indexType.empty() ? absentAttr()
                                                  : valueOnly(texts(IDENT, {frame.indexType})));
        o.attrs.push_back(frame.direction.empty() ? absentAttr()
                                                  : valueOnly(texts(IDENT, {frame.direction})));
        const std::size_t n = frame.frames(), w = frame.width();
        const std::string units = frame.channels.empty() ? "" : frame.channels[0].units;
        if (n >= 2) {
            const double first = frame.values[0], last = frame.values[(n - 1) * w];
            o.attrs.push_back(attr("", numbers(FDOUBL, {(last - first) / double(n - 1)}), units));
            o.attrs.push_back(absentAttr());
            o.attrs.push_back(attr("", numbers(FDOUBL, {std::min(first, last)}), units));
            o.attrs.push_back(attr("", numbers(FDOUBL, {std::max(first, last)}), units));
        }
        s.objects.push_back(std::move(o));
    }
    return s;
}

void putFrameValues(std::string& out, const FrameSpec& frame, std::size_t row) {
    const double* v = frame.values.data() + row * frame.width();
    for (const ChannelSpec& c : frame.channels) {
        const int parts = components(c.code);
        for (std::size_t e = 0; e < c.elements(); ++e, ++v) {
            putNumber(out, c.code, *v);
            for (int k = 1; k < parts; ++k) putNumber(out, c.code, 0.0);
        }
    }
}

}  // namespace

std::vector<Record> logicalFileRecords(const LogicalFileSpec& f, const WriteOptions& options,
                                       std::size_t sequence) {
    std::vector<Record> out;
    out.push_back(eflr(0, fileHeader(f, sequence)));
    out.push_back(eflr(1, originSet(f)));
    if (options.encryptedRecord) {
        // A producer's encrypted parameter record: its body is not a set a reader can parse.
        Record r;
        r.type = 5;
        r.encrypted = true;
        for (int i = 0; i < 37; ++i) r.body.push_back(static_cast<char>((i * 73 + 11) & 0xFF));
        out.push_back(std::move(r));
    }
    if (!f.parameters.empty()) out.push_back(eflr(5, parameterSet(f)));
    if (!f.frames.empty()) {
        out.push_back(eflr(3, channelSet(f)));
        out.push_back(eflr(4, frameSet(f)));
    }
    out.insert(out.end(), f.extraRecords.begin(), f.extraRecords.end());
    for (const FrameSpec& frame : f.frames) {
        const std::size_t n = frame.frames();
        for (std::size_t row = 0; row < n; ++row) {
            Record r;
            r.explicitFormat = false;
            r.type = 0;  // FDATA
            r.body.reserve(16 + frame.name.size() + 8 * frame.width());
            putObname(r.body, {f.origin, 0, frame.name});
            putUvari(r.body, static_cast<std::uint32_t>(row + 1), options.wideUvari ? 4 : 0);
            putFrameValues(r.body, frame, row);
            out.push_back(std::move(r));
        }
    }
    return out;
}

std::uint16_t checksum16(const std::string& bytes) {
    std::uint32_t c = 0;
    for (std::size_t i = 0; i < bytes.size(); i += 2) {
        const std::uint32_t lo = static_cast<unsigned char>(bytes[i]);
        const std::uint32_t hi =
            i + 1 < bytes.size() ? static_cast<unsigned char>(bytes[i + 1]) : 0;
        c += (hi << 8) | lo;
        if (c > 0xFFFFu) c = (c & 0xFFFFu) + 1;
        c = ((c << 1) | (c >> 15)) & 0xFFFFu;
    }
    return static_cast<std::uint16_t>(c);
}

namespace {

// Segments into visible records: each record's body is cut where a segment limit or the
// end of a visible record falls.
class VisibleRecordWriter {
public:
    VisibleRecordWriter(std::string& out, const WriteOptions& o) : m_out(out), m_o(o) {
        if (m_o.visibleRecordLength < 64 || m_o.visibleRecordLength > 16384 ||
            m_o.visibleRecordLength % 2)
            throw std::invalid_argument("visible record length must be even, 64..16384");
    }

    void write(const Record& r) {
        std::string packet;
        if (r.encrypted) {  // size (UNORM, itself included), company code, key bytes
            putBytes(packet, 8, 2);
            putBytes(packet, 440, 2);
            packet += std::string("\x12\x34\x56\x78", 4);
        }
        std::size_t done = 0;
        bool first = true;
        do {
            const std::size_t fixed = 4 + packet.size() + trailer();
            std::size_t space = room();
            if (space < fixed + 13) {
                close();
                space = room();
            }
            std::size_t take = std::min(r.body.size() - done, space - fixed - 1);
            if (m_o.segmentBody) take = std::min(take, m_o.segmentBody);
            const bool last = done + take == r.body.size();
            segment(r, packet, r.body.substr(done, take), first, last);
            done += take;
            first = false;
        } while (done < r.body.size());
    }

    void close() {
        if (m_vrStart == std::string::npos) return;
        const std::size_t length = m_out.size() - m_vrStart;
        m_out[m_vrStart] = static_cast<char>(length >> 8);
        m_out[m_vrStart + 1] = static_cast<char>(length & 0xFF);
        m_vrStart = std::string::npos;
    }

private:
    std::size_t trailer() const { return (m_o.checksums ? 2 : 0) + (m_o.trailingLength ? 2 : 0); }

    // Bytes left in the open visible record (a new one is opened when none is).
    std::size_t room() {
        if (m_vrStart == std::string::npos) {
            m_vrStart = m_out.size();
            m_out += std::string("\0\0\xFF\x01", 4);
        }
        return m_o.visibleRecordLength - (m_out.size() - m_vrStart);
    }

    void segment(const Record& r, const std::string& packet, const std::string& body, bool first,
                 bool last) {
        std::size_t length = 4 + packet.size() + body.size() + trailer();
        std::size_t pad = m_o.padAlways ? 1 : 0;
        while ((length + pad) % 2 || length + pad < 16) ++pad;
        length += pad;
        unsigned char attributes = 0;
        if (r.explicitFormat) attributes |= 0x80;
        if (!first) attributes |= 0x40;
        if (!last) attributes |= 0x20;
        if (r.encrypted) attributes |= 0x10 | 0x08;
        if (m_o.checksums) attributes |= 0x04;
        if (m_o.trailingLength) attributes |= 0x02;
        if (pad) attributes |= 0x01;
        std::string s;
        s.reserve(length);
        putBytes(s, length, 2);
        s.push_back(static_cast<char>(attributes));
        s.push_back(static_cast<char>(r.type));
        std::string summed = packet + body;
        for (std::size_t i = 0; i + 1 < pad; ++i) summed.push_back(0);
        if (pad) summed.push_back(static_cast<char>(pad));
        s += summed;
        if (m_o.checksums) {
            const std::uint16_t c = checksum16(summed);
            s.push_back(static_cast<char>(c & 0xFF));  // low-order byte first, as summed
            s.push_back(static_cast<char>(c >> 8));
        }
        if (m_o.trailingLength) putBytes(s, length, 2);
        m_out += s;
    }

    std::string& m_out;
    const WriteOptions& m_o;
    std::size_t m_vrStart = std::string::npos;
};

std::string storageUnitLabel(const WriteOptions& o) {
    char head[21];
    std::snprintf(head, sizeof head, "   1V1.00RECORD%05zu", o.visibleRecordLength);
    std::string id = o.storageSetId;
    id.resize(60, ' ');
    return std::string(head, 20) + id;
}

// Tape image: 12-byte little-endian marks (type 0 data / 1 file mark, previous mark's
// offset, next mark's offset) before each data record, two file marks at the end.
std::string tapeImage(const std::string& data, std::size_t recordLength) {
    std::string out;
    std::uint32_t previous = 0;
    auto mark = [&](std::uint32_t type, std::size_t payload) {
        const auto here = static_cast<std::uint32_t>(out.size());
        const std::uint32_t fields[3] = {type, previous,
                                         static_cast<std::uint32_t>(here + 12 + payload)};
        for (std::uint32_t f : fields)
            for (int b = 0; b < 4; ++b) out.push_back(static_cast<char>((f >> (8 * b)) & 0xFF));
        previous = here;
    };
    for (std::size_t at = 0; at < data.size(); at += recordLength) {
        const std::size_t n = std::min(recordLength, data.size() - at);
        mark(0, n);
        out.append(data, at, n);
    }
    mark(1, 0);
    mark(1, 0);
    return out;
}

}  // namespace

std::string writeStorageUnit(const std::vector<Record>& records, const WriteOptions& options) {
    std::string out = options.leadingGarbage + storageUnitLabel(options);
    VisibleRecordWriter writer(out, options);
    for (const Record& r : records) writer.write(r);
    writer.close();
    return options.tapeImage ? tapeImage(out, options.tapeRecordLength) : out;
}

std::string writeDlis(const std::vector<LogicalFileSpec>& files, const WriteOptions& options) {
    std::vector<Record> records;
    for (std::size_t i = 0; i < files.size(); ++i) {
        std::vector<Record> r = logicalFileRecords(files[i], options, i + 1);
        records.insert(records.end(), std::make_move_iterator(r.begin()),
                       std::make_move_iterator(r.end()));
    }
    return writeStorageUnit(records, options);
}

void writeDlisFile(const std::string& path, const std::vector<LogicalFileSpec>& files,
                   const WriteOptions& options) {
    const std::string bytes = writeDlis(files, options);
    // Whole or not at all: tests running at once may write and read the same fixture.
    io::AtomicOutput out(path);
    out.stream().write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.commit();
}

Layout checkLayout(const std::string& input) {
    Layout l;
    std::string bytes = input;
    // Remove tape marks (a first mark: type 0 or 1, previous 0, next beyond itself).
    auto le32 = [&](const std::string& b, std::size_t at) {
        std::uint32_t v = 0;
        for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(b[at + k]);
        return v;
    };
    if (bytes.size() >= 12 && le32(bytes, 0) <= 1 && le32(bytes, 4) == 0 && le32(bytes, 8) >= 12) {
        std::string data;
        std::size_t at = 0;
        while (at + 12 <= bytes.size()) {
            const std::uint32_t type = le32(bytes, at), next = le32(bytes, at + 8);
            if (next < at + 12 || next > bytes.size()) {
                l.error = "tape mark at " + std::to_string(at) + " points outside the file";
                return l;
            }
            if (type == 0) data.append(bytes, at + 12, next - at - 12);
            at = next;
        }
        bytes = data;
    }
    const std::size_t sul = bytes.find("V1.00RECORD");
    if (sul == std::string::npos || sul < 4) {
        l.error = "no storage unit label";
        return l;
    }
    std::size_t at = sul - 4 + 80;
    bool open = false;
    while (at < bytes.size()) {
        if (at + 4 > bytes.size()) {
            l.error = "visible record header cut at " + std::to_string(at);
            return l;
        }
        const std::size_t vr = (static_cast<unsigned char>(bytes[at]) << 8) |
                               static_cast<unsigned char>(bytes[at + 1]);
        if (static_cast<unsigned char>(bytes[at + 2]) != 0xFF || bytes[at + 3] != 1 || vr < 20 ||
            vr % 2 || at + vr > bytes.size()) {
            l.error = "bad visible record at " + std::to_string(at);
            return l;
        }
        ++l.visibleRecords;
        std::size_t s = at + 4;
        while (s < at + vr) {
            const std::size_t len = (static_cast<unsigned char>(bytes[s]) << 8) |
                                    static_cast<unsigned char>(bytes[s + 1]);
            const auto attributes = static_cast<unsigned char>(bytes[s + 2]);
            if (len < 16 || len % 2 || s + len > at + vr) {
                l.error = "bad segment length " + std::to_string(len) + " at " + std::to_string(s);
                return l;
            }
            if (bool(attributes & 0x40) != open) {
                l.error = "predecessor bit out of step at " + std::to_string(s);
                return l;
            }
            const std::size_t trailing =
                (static_cast<std::size_t>(static_cast<unsigned char>(bytes[s + len - 2])) << 8) |
                static_cast<unsigned char>(bytes[s + len - 1]);
            if ((attributes & 0x02) && trailing != len) {
                l.error = "trailing length differs at " + std::to_string(s);
                return l;
            }
            open = (attributes & 0x20) != 0;
            ++l.segments;
            if (!open) ++l.records;
            s += len;
        }
        at += vr;
    }
    if (open) l.error = "the last record has a successor";
    return l;
}

}  // namespace caliper3d::test::dlis

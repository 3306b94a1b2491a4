// The representation codes of RP66 v1, Appendix B. Written here rather than taken from a
// library: no DLIS library is packaged for Debian (the open one, dlisio, is not).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "io/dlis/dlis_cursor.h"
#include "io/dlis/dlis_objects.h"

namespace caliper3d::io::dlis {

namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

struct CodeInfo {
    const char* name;
    std::size_t size;  // 0: variable
};

constexpr std::array<CodeInfo, 28> kCodes = {{
    {"", 0},       {"FSHORT", 2}, {"FSINGL", 4},  {"FSING1", 8},  {"FSING2", 12}, {"ISINGL", 4},
    {"VSINGL", 4}, {"FDOUBL", 8}, {"FDOUB1", 16}, {"FDOUB2", 24}, {"CSINGL", 8},  {"CDOUBL", 16},
    {"SSHORT", 1}, {"SNORM", 2},  {"SLONG", 4},   {"USHORT", 1},  {"UNORM", 2},   {"ULONG", 4},
    {"UVARI", 0},  {"IDENT", 0},  {"ASCII", 0},   {"DTIME", 8},   {"ORIGIN", 0},  {"OBNAME", 0},
    {"OBJREF", 0}, {"ATTREF", 0}, {"STATUS", 1},  {"UNITS", 0},
}};

std::uint32_t be32(const unsigned char* b) {
    return (std::uint32_t{b[0]} << 24) | (std::uint32_t{b[1]} << 16) | (std::uint32_t{b[2]} << 8) |
           std::uint32_t{b[3]};
}

std::uint16_t be16(const unsigned char* b) {
    return static_cast<std::uint16_t>((b[0] << 8) | b[1]);
}

double ieeeSingle(const unsigned char* b) {
    const std::uint32_t u = be32(b);
    float f = 0.0F;
    std::memcpy(&f, &u, sizeof f);
    return static_cast<double>(f);
}

double ieeeDouble(const unsigned char* b) {
    const std::uint64_t u = (std::uint64_t{be32(b)} << 32) | be32(b + 4);
    double d = 0.0;
    std::memcpy(&d, &u, sizeof d);
    return d;
}

// FSHORT: a 12-bit two's complement fraction (sign first, point after the sign) and a
// 4-bit exponent of 2.
double fshort(const unsigned char* b) {
    const std::uint16_t v = be16(b);
    int fraction = v >> 4;
    if (fraction & 0x800) fraction -= 0x1000;
    return std::ldexp(static_cast<double>(fraction) / 2048.0, v & 0xF);
}

// ISINGL: IBM System/360 single: sign, 7-bit exponent of 16 excess 64, 24-bit fraction.
double ibmSingle(const unsigned char* b) {
    const std::uint32_t u = be32(b);
    const double fraction = static_cast<double>(u & 0x00FFFFFFU) / 16777216.0;
    const int exponent = static_cast<int>((u >> 24) & 0x7F) - 64;
    const double v = std::ldexp(fraction, 4 * exponent);
    return (u & 0x80000000U) ? -v : v;
}

// VSINGL: VAX F-floating, its 16-bit halves little-endian: sign, 8-bit exponent excess
// 128, 23-bit fraction after a hidden 0.1 (binary). Exponent 0 with the sign set is
// reserved (NaN).
double vaxSingle(const unsigned char* b) {
    const std::uint32_t v = (std::uint32_t{b[1]} << 24) | (std::uint32_t{b[0]} << 16) |
                            (std::uint32_t{b[3]} << 8) | std::uint32_t{b[2]};
    const std::uint32_t exponent = (v >> 23) & 0xFF;
    const bool negative = (v & 0x80000000U) != 0;
    if (exponent == 0) return negative ? kNan : 0.0;
    const double significand = static_cast<double>((v & 0x007FFFFFU) | 0x00800000U) / 16777216.0;
    const double x = std::ldexp(significand, static_cast<int>(exponent) - 128);
    return negative ? -x : x;
}

std::string dtimeText(const unsigned char* b) {
    static const char* kZones[3] = {"local standard", "local daylight savings", "GMT"};
    const int zone = b[1] >> 4;
    char text[64];
    std::snprintf(text, sizeof text, "%04d-%02d-%02d %02d:%02d:%02d.%03d", 1900 + b[0], b[1] & 0xF,
                  b[2], b[3], b[4], b[5], be16(b + 6));
    std::string out(text);
    if (zone < 3) out += std::string(" ") + kZones[zone];
    return out;
}

std::string shortest(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

}  // namespace

std::string repCodeName(int code) {
    if (code >= 1 && code <= 27) return kCodes[static_cast<std::size_t>(code)].name;
    return "code " + std::to_string(code);
}

std::size_t repCodeSize(int code) {
    return code >= 1 && code <= 27 ? kCodes[static_cast<std::size_t>(code)].size : 0;
}

double decodeNumber(int code, const unsigned char* b) {
    switch (code) {
        case kFSHORT:
            return fshort(b);
        case kFSINGL:
        case kFSING1:
        case kFSING2:
        case kCSINGL:
            return ieeeSingle(b);
        case kISINGL:
            return ibmSingle(b);
        case kVSINGL:
            return vaxSingle(b);
        case kFDOUBL:
        case kFDOUB1:
        case kFDOUB2:
        case kCDOUBL:
            return ieeeDouble(b);
        case kSSHORT:
            return static_cast<double>(static_cast<std::int8_t>(b[0]));
        case kSNORM:
            return static_cast<double>(static_cast<std::int16_t>(be16(b)));
        case kSLONG:
            return static_cast<double>(static_cast<std::int32_t>(be32(b)));
        case kUSHORT:
        case kSTATUS:
            return static_cast<double>(b[0]);
        case kUNORM:
            return static_cast<double>(be16(b));
        case kULONG:
            return static_cast<double>(be32(b));
        default:
            return kNan;
    }
}

std::uint8_t Cursor::peek() const {
    if (m_pos >= m_size) throw BodyError(m_pos, "expected another component, found the end");
    return m_begin[m_pos];
}

const unsigned char* Cursor::take(std::size_t n) {
    if (n > m_size - m_pos)
        throw BodyError(m_pos, "expected " + std::to_string(n) + " more bytes, found " +
                                   std::to_string(m_size - m_pos));
    const unsigned char* p = m_begin + m_pos;
    m_pos += n;
    return p;
}

void Cursor::skip(std::size_t n) {
    take(n);
}

std::uint8_t Cursor::ushort() {
    return *take(1);
}

std::uint16_t Cursor::unorm() {
    return be16(take(2));
}

std::uint32_t Cursor::ulong() {
    return be32(take(4));
}

std::uint32_t Cursor::uvari() {
    const std::uint8_t first = peek();
    if ((first & 0x80) == 0) return *take(1);
    if ((first & 0xC0) == 0x80) return be16(take(2)) & 0x3FFFU;
    return be32(take(4)) & 0x3FFFFFFFU;
}

std::string Cursor::ident() {
    const std::size_t n = ushort();
    const unsigned char* p = take(n);
    return std::string(reinterpret_cast<const char*>(p), n);
}

std::string Cursor::ascii() {
    const std::size_t n = uvari();
    const unsigned char* p = take(n);
    return std::string(reinterpret_cast<const char*>(p), n);
}

ObjectName Cursor::obname() {
    ObjectName name;
    name.origin = uvari();
    name.copy = ushort();
    name.id = ident();
    return name;
}

Value Cursor::value(int code) {
    switch (code) {
        case kFSING1:
        case kCSINGL:
        case kFSING2:
        case kFDOUB1:
        case kCDOUBL:
        case kFDOUB2: {
            // Compounds: two or three IEEE components of 4 or 8 bytes.
            const std::size_t n = code == kFSING2 || code == kFDOUB2 ? 3 : 2;
            const std::size_t part = repCodeSize(code) / n;
            const unsigned char* p = take(part * n);
            std::vector<double> parts;
            for (std::size_t i = 0; i < n; ++i)
                parts.push_back(part == 4 ? ieeeSingle(p + 4 * i) : ieeeDouble(p + 8 * i));
            return parts;
        }
        case kUVARI:
        case kORIGIN:
            return static_cast<double>(uvari());
        case kIDENT:
        case kUNITS:
            return ident();
        case kASCII:
            return ascii();
        case kDTIME: {
            const unsigned char* p = take(8);
            if ((p[1] & 0xF) < 1 || (p[1] & 0xF) > 12 || (p[1] >> 4) > 2)
                throw BodyError(m_pos - 8, "expected a date (DTIME), found month " +
                                               std::to_string(p[1] & 0xF) + " time zone " +
                                               std::to_string(p[1] >> 4));
            return dtimeText(p);
        }
        case kOBNAME:
            return obname();
        case kOBJREF: {
            ObjectRef r;
            r.type = ident();
            r.name = obname();
            return r;
        }
        case kATTREF: {
            AttributeRef r;
            r.type = ident();
            r.name = obname();
            r.label = ident();
            return r;
        }
        default:
            break;
    }
    const std::size_t size = repCodeSize(code);
    if (size == 0)
        throw BodyError(m_pos,
                        "expected a representation code 1 to 27, found " + std::to_string(code));
    return decodeNumber(code, take(size));
}

void Cursor::skipValue(int code) {
    const std::size_t size = repCodeSize(code);
    if (size) {
        take(size);
        return;
    }
    (void)value(code);
}

double Attribute::number(std::size_t i) const {
    if (i >= values.size()) return kNan;
    const Value& v = values[i];
    if (const double* d = std::get_if<double>(&v)) return *d;
    if (const auto* parts = std::get_if<std::vector<double>>(&v))
        return parts->empty() ? kNan : parts->front();
    return kNan;
}

std::string Attribute::text(std::size_t i) const {
    if (i >= values.size()) return "";
    const Value& v = values[i];
    if (const double* d = std::get_if<double>(&v)) return shortest(*d);
    if (const auto* parts = std::get_if<std::vector<double>>(&v)) {
        std::string out;
        for (double p : *parts) out += (out.empty() ? "" : " ") + shortest(p);
        return out;
    }
    if (const auto* s = std::get_if<std::string>(&v)) {
        // Producers pad fixed-width texts with blanks.
        const std::size_t begin = s->find_first_not_of(' ');
        if (begin == std::string::npos) return std::string();
        return s->substr(begin, s->find_last_not_of(' ') + 1 - begin);
    }
    if (const auto* n = std::get_if<ObjectName>(&v)) return n->id;
    if (const auto* r = std::get_if<ObjectRef>(&v)) return r->name.id;
    if (const auto* a = std::get_if<AttributeRef>(&v)) return a->name.id + "." + a->label;
    return "";
}

const Attribute* Object::attribute(std::string_view label) const {
    for (const Attribute& a : attributes)
        if (a.label == label) return a.absent ? nullptr : &a;
    return nullptr;
}

std::size_t Channel::elements() const {
    std::size_t n = 1;
    for (std::uint32_t d : dimension) n *= d;
    return n;
}

const Channel* LogicalFile::channel(const ObjectName& name) const {
    for (const Channel& c : channels)
        if (c.name == name) return &c;
    return nullptr;
}

std::vector<const Object*> LogicalFile::objects(std::string_view type) const {
    std::vector<const Object*> out;
    for (const Set& s : sets) {
        // A redundant set repeats objects already given; a replacement set's objects stand
        // for the earlier ones of the same name (RP66 v1 3.2.2.1).
        if (s.type != type || s.redundant) continue;
        for (const Object& o : s.objects) {
            auto same = std::find_if(out.begin(), out.end(),
                                     [&](const Object* p) { return p->name == o.name; });
            if (s.replacement && same != out.end())
                *same = &o;
            else
                out.push_back(&o);
        }
    }
    return out;
}

}  // namespace caliper3d::io::dlis

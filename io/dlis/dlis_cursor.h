#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "io/dlis/dlis_objects.h"

namespace caliper3d::io::dlis {

// A logical record's body that ends before what it declares, or holds a value that cannot
// be. `at` is the byte of the body where it was found.
class BodyError : public std::runtime_error {
public:
    BodyError(std::size_t at, const std::string& what) : std::runtime_error(what), at(at) {}
    std::size_t at;
};

// Reads the representation codes of RP66 v1 (Appendix B) from a logical record's body,
// never past its end: a value cut short throws BodyError.
class Cursor {
public:
    Cursor(const unsigned char* begin, std::size_t size) : m_begin(begin), m_size(size) {}

    std::size_t position() const { return m_pos; }
    std::size_t remaining() const { return m_size - m_pos; }
    bool atEnd() const { return m_pos >= m_size; }
    const unsigned char* here() const { return m_begin + m_pos; }
    std::uint8_t peek() const;
    void skip(std::size_t n);

    std::uint8_t ushort();
    std::uint16_t unorm();
    std::uint32_t ulong();
    std::uint32_t uvari();
    std::string ident();  // IDENT and UNITS: a USHORT length, then the characters
    std::string ascii();  // a UVARI length, then the characters
    ObjectName obname();

    // One value of `code`; BodyError for a code outside 1..27.
    Value value(int code);
    // Skips one value of `code` (frame data of a channel not wanted).
    void skipValue(int code);

private:
    const unsigned char* take(std::size_t n);

    const unsigned char* m_begin;
    std::size_t m_size;
    std::size_t m_pos = 0;
};

// The number one value of a fixed-size numeric code (1..17, 26) holds, from its bytes
// (the first component of a compound); NaN for other codes.
double decodeNumber(int code, const unsigned char* bytes);

}  // namespace caliper3d::io::dlis

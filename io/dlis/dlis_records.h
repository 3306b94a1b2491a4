#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "io/diagnostics.h"
#include "io/dlis/dlis_objects.h"

namespace caliper3d::io::dlis {

// Damage in the file's envelope (storage unit label, visible records, segment headers)
// that ends reading: nothing after it can be found safely. `offset` is the file's byte.
class EnvelopeError : public std::runtime_error {
public:
    EnvelopeError(std::size_t offset, const std::string& what)
        : std::runtime_error(what), offset(offset) {}
    std::size_t offset;
};

// One whole logical record, its segments joined and their trailers (padding, checksum,
// trailing length) removed. `body` is valid until the next call of RecordStream::next.
struct LogicalRecord {
    bool explicitlyFormatted = false;  // an EFLR (else an IFLR)
    int type = 0;
    std::size_t offset = 0;  // the file's byte of its first segment header
    bool encrypted = false;  // its body is not readable (left empty)
    const unsigned char* body = nullptr;
    std::size_t size = 0;
};

// Walks the visible envelope of a DLIS file (RP66 v1 chapter 2): the storage unit label
// (leading garbage allowed), an optional tape-image wrapper, visible records and logical
// record segments. Record-level damage (pad bytes longer than the segment, segments whose
// attributes disagree) skips that record with a warning; envelope damage throws
// EnvelopeError from next().
class RecordStream {
public:
    // Reads the label (and removes tape marks). Throws EnvelopeError when neither a label
    // nor a visible record is found near the start.
    RecordStream(std::string_view bytes, const std::string& name, Diagnostics* diagnostics);

    // The next whole record; false at the end of the file.
    bool next(LogicalRecord& record);

    // The file's byte of byte `pos` of the (tape marks removed) data.
    std::size_t fileOffset(std::size_t pos) const;

    DlisIndex label;  // the label's fields (files left empty)

private:
    void unwrapTapeImage();
    void findLabel();
    void skipBetweenVisibleRecords();
    bool nextSegment(std::size_t& start, std::size_t& length, unsigned char& attributes, int& type);
    void warn(std::size_t pos, const std::string& message);
    void warnAtFileByte(std::size_t byte, const std::string& message);

    std::string_view m_data;  // the file, or m_unwrapped
    std::string m_unwrapped;
    // Tape image: where each stretch of m_unwrapped lies in the file.
    std::vector<std::pair<std::size_t, std::size_t>> m_stretches;
    std::string m_name;
    Diagnostics* m_diagnostics;
    std::size_t m_pos = 0;    // next visible record or segment header
    std::size_t m_vrEnd = 0;  // end of the current visible record (0: none open)
    bool m_cut = false;       // the last visible record runs past the end of the file
    std::string m_scratch;    // a record of several segments, joined
};

}  // namespace caliper3d::io::dlis

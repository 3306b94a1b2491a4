#include "io/dlis/dlis_records.h"

#include <algorithm>
#include <cctype>
#include <cstdint>

namespace caliper3d::io::dlis {

namespace {

constexpr std::size_t kLabelBytes = 80;
constexpr std::size_t kSearchBytes = 256;  // leading garbage looked through for the label
constexpr std::size_t kTapeMarkBytes = 12;

std::uint32_t le32(const unsigned char* b) {
    return std::uint32_t{b[0]} | (std::uint32_t{b[1]} << 8) | (std::uint32_t{b[2]} << 16) |
           (std::uint32_t{b[3]} << 24);
}

std::size_t be16(const unsigned char* b) {
    return (std::size_t{b[0]} << 8) | b[1];
}

const unsigned char* bytesOf(std::string_view s) {
    return reinterpret_cast<const unsigned char*>(s.data());
}

// A visible record header: a length of at least a header, then 0xFF and the version 1.
bool looksLikeVisibleRecord(std::string_view d, std::size_t at) {
    if (at + 4 > d.size()) return false;
    const unsigned char* b = bytesOf(d) + at;
    return b[2] == 0xFF && b[3] == 0x01 && be16(b) >= 8;
}

std::string printable(std::string_view s) {
    std::string out;
    for (char c : s) out += std::isprint(static_cast<unsigned char>(c)) ? c : '.';
    return out;
}

// "V1.00RECORD" at `at` + 4 (after the sequence number).
bool labelAt(std::string_view d, std::size_t at) {
    return d.size() >= at + 15 && d.compare(at + 4, 3, "V1.") == 0 &&
           d.compare(at + 9, 6, "RECORD") == 0;
}

bool tapeMarkAt(std::string_view d, std::size_t at, std::size_t previous) {
    if (at + kTapeMarkBytes > d.size()) return false;
    const unsigned char* b = bytesOf(d) + at;
    const std::uint32_t type = le32(b), prev = le32(b + 4), next = le32(b + 8);
    return type <= 1 && prev == previous && next >= at + kTapeMarkBytes;
}

// The first mark of a tape image: a mark whose record ends within the file, or is followed by
// a label, a visible record or another mark (so that NUL bytes of leading garbage are not
// taken for one).
bool tapeImageAt(std::string_view d) {
    if (!tapeMarkAt(d, 0, 0)) return false;
    const std::size_t next = le32(bytesOf(d) + 8);
    return next <= d.size() || labelAt(d, kTapeMarkBytes) ||
           looksLikeVisibleRecord(d, kTapeMarkBytes) || tapeMarkAt(d, kTapeMarkBytes, 0);
}

}  // namespace

bool looksLikeDlis(std::string_view start) {
    // A tape-image mark (NUL bytes a text never starts with) wraps nothing but DLIS here.
    if (tapeImageAt(start)) return true;
    const std::size_t from = 0;
    const std::size_t last = std::min(start.size(), from + kSearchBytes);
    for (std::size_t at = from; at <= last && at + 15 <= start.size(); ++at)
        if (labelAt(start, at)) return true;
    // No label (or a damaged one): a visible record header, then a segment header that fits
    // in it (0xFF never occurs in UTF-8 text).
    for (std::size_t at = from; at <= last && at + 8 <= start.size(); ++at) {
        if (!looksLikeVisibleRecord(start, at)) continue;
        const std::size_t segment = be16(bytesOf(start) + at + 4);
        if (segment >= 4 && segment <= be16(bytesOf(start) + at)) return true;
    }
    return false;
}

RecordStream::RecordStream(std::string_view bytes, const std::string& name,
                           Diagnostics* diagnostics)
    : m_data(bytes), m_name(name), m_diagnostics(diagnostics) {
    if (tapeImageAt(m_data)) unwrapTapeImage();
    findLabel();
}

void RecordStream::warn(std::size_t pos, const std::string& message) {
    warnAtFileByte(fileOffset(pos), message);
}

void RecordStream::warnAtFileByte(std::size_t byte, const std::string& message) {
    if (m_diagnostics)
        m_diagnostics->warn(m_name, 0, "byte " + std::to_string(byte) + ": " + message);
}

std::size_t RecordStream::fileOffset(std::size_t pos) const {
    if (m_stretches.empty()) return pos;
    // m_stretches: (start in m_unwrapped, start in the file), increasing.
    auto it = std::upper_bound(
        m_stretches.begin(), m_stretches.end(), pos,
        [](std::size_t p, const std::pair<std::size_t, std::size_t>& s) { return p < s.first; });
    if (it == m_stretches.begin()) return pos;
    --it;
    return it->second + (pos - it->first);
}

// Tape image format: each record of data is preceded by a 12-byte mark (type 0 data or 1
// file mark, the offset of the previous mark, the offset of the next), little endian.
void RecordStream::unwrapTapeImage() {
    label.tapeImage = true;
    std::size_t at = 0, previous = 0;
    while (at + kTapeMarkBytes <= m_data.size()) {
        if (!tapeMarkAt(m_data, at, previous)) {
            // Tape images are often padded with zeros after their last marks.
            if (std::all_of(m_data.begin() + static_cast<std::ptrdiff_t>(at), m_data.end(),
                            [](char c) { return c == 0; }))
                break;
            warnAtFileByte(at,
                           "tape-image mark is not a mark (type, previous, next); the rest "
                           "is not read");
            break;
        }
        const unsigned char* b = bytesOf(m_data) + at;
        const std::size_t next = le32(b + 8);
        const std::size_t end = std::min<std::size_t>(next, m_data.size());
        if (le32(b) == 0 && end > at + kTapeMarkBytes) {
            m_stretches.emplace_back(m_unwrapped.size(), at + kTapeMarkBytes);
            m_unwrapped.append(m_data.substr(at + kTapeMarkBytes, end - at - kTapeMarkBytes));
        }
        if (next > m_data.size()) {
            warnAtFileByte(at, "tape-image record runs past the end of the file");
            break;
        }
        previous = at;
        at = next;
    }
    if (at < m_data.size() && at + kTapeMarkBytes > m_data.size() &&
        !std::all_of(m_data.begin() + static_cast<std::ptrdiff_t>(at), m_data.end(),
                     [](char c) { return c == 0; }))
        warnAtFileByte(at, "tape-image mark cut short: " + std::to_string(m_data.size() - at) +
                               " of its " + std::to_string(kTapeMarkBytes) + " bytes");
    m_data = m_unwrapped;
}

void RecordStream::findLabel() {
    const std::size_t last = std::min(m_data.size(), kSearchBytes);
    std::size_t at = 0;
    bool found = false;
    for (; at <= last && at + 15 <= m_data.size(); ++at)
        if (labelAt(m_data, at)) {
            found = true;
            break;
        }
    if (found) {
        if (at > 0) warn(0, std::to_string(at) + " bytes before the storage unit label; skipped");
        if (at + kLabelBytes > m_data.size())
            throw EnvelopeError(fileOffset(at), "expected an 80-byte storage unit label, found " +
                                                    std::to_string(m_data.size() - at) +
                                                    " bytes before the end of the file");
        const std::string_view sul = m_data.substr(at, kLabelBytes);
        label.sulOffset = fileOffset(at);
        label.version = std::string(sul.substr(4, 5));
        label.structure = std::string(sul.substr(9, 6));
        const std::string length(sul.substr(15, 5));
        label.maxRecordLength = 0;
        for (char c : length)
            if (std::isdigit(static_cast<unsigned char>(c)))
                label.maxRecordLength =
                    label.maxRecordLength * 10 + static_cast<std::size_t>(c - '0');
        std::string id(sul.substr(20, 60));
        while (!id.empty() && (id.back() == ' ' || id.back() == '\0')) id.pop_back();
        label.storageSetId = id;
        m_pos = at + kLabelBytes;
    } else {
        label.hasSul = false;
        m_pos = 0;
    }
    // The first visible record, past garbage if need be.
    const std::size_t from = m_pos;
    std::size_t vr = from;
    const std::size_t lastVr = std::min(m_data.size(), from + kSearchBytes);
    while (vr < lastVr && !looksLikeVisibleRecord(m_data, vr)) ++vr;
    if (vr >= lastVr || !looksLikeVisibleRecord(m_data, vr)) {
        if (!found)
            throw EnvelopeError(fileOffset(0),
                                "expected a DLIS storage unit label ('V1.00RECORD') or a visible "
                                "record, found '" +
                                    printable(m_data.substr(0, 24)) + "'");
        if (m_data.size() - from < 4)
            throw EnvelopeError(fileOffset(from),
                                "expected a visible record after the storage unit label, found "
                                "the end of the file");
        throw EnvelopeError(fileOffset(from),
                            "expected a visible record (length, 0xFF, 0x01) after the storage "
                            "unit label, found none in the next " +
                                std::to_string(lastVr - from) + " bytes");
    }
    if (!found) warn(vr, "no storage unit label; reading from the first visible record");
    if (vr > from)
        warn(from, std::to_string(vr - from) + " bytes before the first visible record; skipped");
    m_pos = vr;
}

// What may lie between visible records: the label of the next storage unit of a set, or
// in a tape image the bytes that align a record to its mark.
void RecordStream::skipBetweenVisibleRecords() {
    for (;;) {
        if (m_pos >= m_data.size() || looksLikeVisibleRecord(m_data, m_pos)) return;
        if (labelAt(m_data, m_pos) && m_pos + kLabelBytes <= m_data.size()) {
            m_pos += kLabelBytes;
            continue;
        }
        if (!m_stretches.empty()) {
            auto it =
                std::upper_bound(m_stretches.begin(), m_stretches.end(), m_pos,
                                 [](std::size_t p, const std::pair<std::size_t, std::size_t>& s) {
                                     return p < s.first;
                                 });
            if (it != m_stretches.end() && it->first - m_pos <= 3) {
                m_pos = it->first;
                continue;
            }
        }
        return;
    }
}

// The next segment header, opening the next visible record when the current one is done.
// False at a clean end of the data.
bool RecordStream::nextSegment(std::size_t& start, std::size_t& length, unsigned char& attributes,
                               int& type) {
    const unsigned char* d = bytesOf(m_data);
    if (m_pos >= m_vrEnd) {
        m_vrEnd = 0;
        skipBetweenVisibleRecords();
        if (m_pos >= m_data.size()) return false;
        if (!m_stretches.empty() && m_data.size() - m_pos <= 3) return false;  // alignment
        if (m_data.size() - m_pos < 4)
            throw EnvelopeError(fileOffset(m_pos), "expected a visible record header, found " +
                                                       std::to_string(m_data.size() - m_pos) +
                                                       " bytes before the end of the file");
        const unsigned char* v = d + m_pos;
        if (v[2] != 0xFF)
            throw EnvelopeError(fileOffset(m_pos),
                                "expected a visible record header (length, 0xFF, 0x01), found "
                                "bytes " +
                                    std::to_string(v[0]) + " " + std::to_string(v[1]) + " " +
                                    std::to_string(v[2]) + " " + std::to_string(v[3]));
        if (v[3] != 0x01)
            warn(m_pos,
                 "visible record of version " + std::to_string(v[3]) + ", read as version 1");
        const std::size_t vrLength = be16(v);
        if (vrLength < 8)
            throw EnvelopeError(fileOffset(m_pos),
                                "expected a visible record of at least 8 bytes, "
                                "found length " +
                                    std::to_string(vrLength));
        m_vrEnd = m_pos + vrLength;
        if (m_vrEnd > m_data.size()) {
            // Cut short: the whole records before the cut are still read.
            warn(m_pos, "visible record of " + std::to_string(vrLength) +
                            " bytes runs past the end of the file (cut short); the records "
                            "before the cut are read");
            m_vrEnd = m_data.size();
            m_cut = true;
        }
        m_pos += 4;
    }
    if (m_cut && (m_vrEnd - m_pos < 4 || m_pos + be16(d + m_pos) > m_vrEnd))
        throw EnvelopeError(fileOffset(m_pos),
                            "the file ends inside a logical record segment "
                            "(cut short)");
    if (m_vrEnd - m_pos < 4)
        throw EnvelopeError(fileOffset(m_pos), "expected a logical record segment header, found " +
                                                   std::to_string(m_vrEnd - m_pos) +
                                                   " bytes before the end of the visible record");
    const unsigned char* s = d + m_pos;
    length = be16(s);
    attributes = s[2];
    type = s[3];
    if (length < 4)
        throw EnvelopeError(fileOffset(m_pos), "segment length " + std::to_string(length) +
                                                   " is shorter than its own header");
    if (m_pos + length > m_vrEnd)
        throw EnvelopeError(fileOffset(m_pos), "segment of " + std::to_string(length) +
                                                   " bytes runs past its visible record");
    start = m_pos;
    m_pos += length;
    return true;
}

bool RecordStream::next(LogicalRecord& record) {
    for (;;) {
        std::size_t start = 0, length = 0;
        unsigned char attributes = 0;
        int type = 0;
        if (!nextSegment(start, length, attributes, type)) return false;
        record = LogicalRecord{};
        record.explicitlyFormatted = (attributes & 0x80) != 0;
        record.type = type;
        record.offset = fileOffset(start);
        record.encrypted = (attributes & 0x10) != 0;
        if (attributes & 0x40)
            warn(start, "segment continues a record that did not start; read as a record");
        bool single = true, damaged = false;
        m_scratch.clear();
        std::string problem;
        for (;;) {
            const unsigned char* d = bytesOf(m_data) + start;
            std::size_t bodyBegin = 4, bodyEnd = length;
            if (!record.encrypted) {
                if (attributes & 0x02) bodyEnd -= std::min<std::size_t>(2, bodyEnd - bodyBegin);
                if (attributes & 0x04) bodyEnd -= std::min<std::size_t>(2, bodyEnd - bodyBegin);
                if (attributes & 0x01) {
                    const std::size_t pad = bodyEnd > bodyBegin ? d[bodyEnd - 1] : 0;
                    if (bodyEnd <= bodyBegin || pad > bodyEnd - bodyBegin) {
                        damaged = true;
                        problem = "pad count " + std::to_string(pad) + " exceeds the segment's " +
                                  std::to_string(bodyEnd - bodyBegin) + " bytes";
                    } else {
                        bodyEnd -= pad;
                    }
                }
            }
            if (!damaged && !record.encrypted) {
                const std::string_view part(reinterpret_cast<const char*>(d) + bodyBegin,
                                            bodyEnd - bodyBegin);
                if (single) {
                    record.body = d + bodyBegin;
                    record.size = part.size();
                } else {
                    if (m_scratch.empty() && record.size)
                        m_scratch.assign(reinterpret_cast<const char*>(record.body), record.size);
                    m_scratch.append(part);
                }
            }
            if (!(attributes & 0x20)) break;
            const unsigned char previousAttributes = attributes;
            const int previousType = type;
            if (!nextSegment(start, length, attributes, type))
                throw EnvelopeError(fileOffset(m_pos),
                                    "logical record at byte " + std::to_string(record.offset) +
                                        " cut short: its next segment is missing");
            single = false;
            if (!(attributes & 0x40) || (attributes & 0x80) != (previousAttributes & 0x80)) {
                damaged = true;
                problem = "its segments disagree on the record's form or order";
            } else if (type != previousType) {
                warn(start, "segment of type " + std::to_string(type) +
                                " continues a record of type " + std::to_string(previousType) +
                                "; read as type " + std::to_string(previousType));
                type = previousType;
            }
        }
        if (!single && !damaged && !record.encrypted) {
            record.body = reinterpret_cast<const unsigned char*>(m_scratch.data());
            record.size = m_scratch.size();
        }
        if (record.encrypted) {
            record.body = nullptr;
            record.size = 0;
        }
        if (damaged) {
            warnAtFileByte(record.offset, "logical record skipped: " + problem);
            continue;
        }
        return true;
    }
}

}  // namespace caliper3d::io::dlis

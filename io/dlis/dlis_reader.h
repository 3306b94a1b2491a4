#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "io/diagnostics.h"
#include "io/dlis/dlis_objects.h"

namespace caliper3d::io::dlis {

// True when `start` (the first bytes of a file) holds a DLIS storage unit label within its
// first 256 bytes ("V1.00RECORD" after a 4-character sequence number, leading garbage
// allowed), or starts with a tape-image mark around one.
bool looksLikeDlis(std::string_view start);

// Reads the storage unit label and every logical file's explicitly formatted records of a
// DLIS (RP66 v1) file held in `bytes`; frame data records are counted per frame, not
// decoded. Throws ParseError naming `name` and the byte offset (in the message) for what is
// not DLIS, or is cut short or malformed before a first logical file is read whole; later
// damage ends the index at the last whole record with a warning naming the offset.
// Encrypted records are skipped, counted in one warning per logical file.
DlisIndex indexDlis(std::string_view bytes, const std::string& name, Diagnostics* diagnostics);

// One wanted channel of a frame: its position in Frame::channels. All its elements are
// delivered, in the channel's order.
struct FrameRead {
    std::vector<std::size_t> channels;  // positions in Frame::channels, any order
    // Elements delivered per frame: the sum of the wanted channels' elements.
    std::size_t width = 0;
};

// Called for each frame of the wanted frame, in file order, with its frame number, the
// wanted channels' values as numbers (NaN where a value is not a number) and the byte
// offset of its record. Return false to stop.
using FrameConsumer =
    std::function<bool(std::uint32_t frameNumber, const double* values, std::size_t offset)>;

// Decodes the frames of frame `frame` of logical file `file` (indices into `index`),
// decoding only the channels in `wanted` (the offsets of the others are skipped using
// their codes and dimensions). A record cut short or holding less than a whole frame is
// skipped with a warning naming its offset.
void readFrames(std::string_view bytes, const std::string& name, const DlisIndex& index,
                std::size_t file, std::size_t frame, const FrameRead& wanted,
                const FrameConsumer& consumer, Diagnostics* diagnostics);

// The elements a frame read delivers for `channels` of `frame` in `file`.
FrameRead frameRead(const LogicalFile& file, const Frame& frame, std::vector<std::size_t> channels);

}  // namespace caliper3d::io::dlis

// Any bytes through the DLIS reader: the index, every frame of every logical file, and the
// log reader's DLIS path. A ParseError, warnings or a log; nothing else.
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/dlis/dlis_reader.h"
#include "io/log_reader.h"
#include "io/parse_error.h"

namespace {

void readEveryFrame(const std::string& bytes) {
    using namespace caliper3d::io;
    Diagnostics diagnostics;
    const dlis::DlisIndex index = dlis::indexDlis(bytes, "fuzz.dlis", &diagnostics);
    for (std::size_t f = 0; f < index.files.size(); ++f)
        for (std::size_t j = 0; j < index.files[f].frames.size(); ++j) {
            const dlis::Frame& frame = index.files[f].frames[j];
            std::vector<std::size_t> all(frame.channels.size());
            for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
            const dlis::FrameRead read = dlis::frameRead(index.files[f], frame, all);
            double sum = 0.0;
            dlis::readFrames(
                bytes, "fuzz.dlis", index, f, j, read,
                [&](std::uint32_t, const double* values, std::size_t) {
                    for (std::size_t i = 0; i < read.width; ++i) sum += values[i];
                    return true;
                },
                &diagnostics);
        }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string bytes(reinterpret_cast<const char*>(data), size);
    // Steer inputs without a storage unit label past it.
    if (!caliper3d::io::dlis::looksLikeDlis(bytes))
        bytes = "   1V1.00RECORD08192" + std::string(60, ' ') + bytes;
    try {
        readEveryFrame(bytes);
    } catch (const caliper3d::io::ParseError&) {
    }
    caliper3d::io::StreamOptions stream;
    stream.chunkRows = 3;
    try {
        caliper3d::io::loadCaliperText(bytes, "fuzz.dlis", {}, stream);
    } catch (const caliper3d::io::ParseError&) {
    }
    return 0;
}

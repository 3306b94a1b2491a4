// Any bytes through the LAS path of the log reader (both threads, small
// blocks so that splitting is exercised): a ParseError or a log, nothing else.
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/log_reader.h"
#include "io/parse_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string text = "~";  // steer most inputs into LAS
    text.append(reinterpret_cast<const char*>(data), size);
    caliper3d::io::StreamOptions stream;
    stream.blockBytes = 4096;
    stream.chunkRows = 3;
    try {
        caliper3d::io::loadCaliperText(text, "fuzz.las", {}, stream);
    } catch (const caliper3d::io::ParseError&) {
    }
    try {  // the same bytes as they came: column text or LAS, detected
        caliper3d::io::loadCaliperText(std::string_view(text).substr(1), "fuzz", {}, stream);
    } catch (const caliper3d::io::ParseError&) {
    }
    return 0;
}

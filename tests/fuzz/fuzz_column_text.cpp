// Any bytes through both column-text readers (the whole-text one and the
// streaming one, with radii-only detection): a ParseError or a table.
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/log_reader.h"
#include "io/parse_error.h"
#include "support/column_text_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        caliper3d::io::parseColumnText(text, "fuzz.txt", {});
    } catch (const caliper3d::io::ParseError&) {
    }
    caliper3d::io::ReadOptions options;
    options.armCount = 3;
    caliper3d::io::StreamOptions stream;
    stream.blockBytes = 4096;
    stream.chunkRows = 2;
    try {
        caliper3d::io::loadCaliperText(text, "fuzz.txt", options, stream);
    } catch (const caliper3d::io::ParseError&) {
    }
    return 0;
}

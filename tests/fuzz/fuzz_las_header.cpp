// Any bytes through the LAS header parser and the whole-text LAS reader
// (wrapped data, LAS 3.0 groups): a ParseError or a header, nothing else.
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/las_header.h"
#include "io/las_reader.h"
#include "io/parse_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    caliper3d::io::Diagnostics diagnostics;
    try {
        caliper3d::io::parseLasHeader(text, "fuzz.las", &diagnostics);
        caliper3d::io::readLas(text, "fuzz.las", {}, &diagnostics);
    } catch (const caliper3d::io::ParseError&) {
    }
    return 0;
}

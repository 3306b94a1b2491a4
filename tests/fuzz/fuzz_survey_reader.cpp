// Any bytes through the deviation survey reader (header detection, units
// line, delimiters, decimal comma, footers): a ParseError or a table whose
// depths never decrease, nothing else.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "io/parse_error.h"
#include "io/survey_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const caliper3d::io::SurveyTable s = caliper3d::io::parseSurvey(text, "fuzz.csv");
        // What the reader promises: at least two stations, MD never decreasing,
        // one inclination and azimuth per station.
        if (s.stationCount() < 2 || s.inc_deg.size() != s.stationCount() ||
            s.azi_deg.size() != s.stationCount())
            std::abort();
        for (std::size_t i = 1; i < s.stationCount(); ++i)
            if (s.md_m[i] < s.md_m[i - 1]) std::abort();
    } catch (const caliper3d::io::ParseError&) {
    }
    return 0;
}

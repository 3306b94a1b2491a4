// Any bytes through the batch manifest reader, as CSV (first byte even) or JSON (odd): a
// ParseError, or rows numbered in order each with a file or the reason it cannot run. The
// seeds (corpus/manifest) start with that byte: "0" then CSV, "1" then JSON.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "app/batch_manifest.h"
#include "io/parse_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const bool json = (data[0] & 1) != 0;
    std::istringstream in(std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
    try {
        const caliper3d::app::Manifest m =
            caliper3d::app::parseManifest(json ? "fuzz/m.json" : "fuzz/m.csv", in);
        for (std::size_t i = 0; i < m.rows.size(); ++i) {
            const caliper3d::app::ManifestRow& row = m.rows[i];
            if (row.index != i) std::abort();
            if (row.problem.empty() && (row.file.empty() || row.verbs.empty())) std::abort();
        }
    } catch (const caliper3d::io::ParseError&) {
    }
    return 0;
}

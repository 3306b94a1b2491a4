#pragma once

#include <cstddef>
#include <cstdio>
#include <exception>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "io/diagnostics.h"
#include "reconstruction/analysis/hole_volume.h"
#include "reconstruction/analysis/run_comparison.h"
#include "reconstruction/analysis/well_analysis.h"
#include "reconstruction/analysis/zone_detection.h"

namespace caliper3d::reconstruction {
struct WellAnalysis;
}

namespace caliper3d::app {

// Where and why an input failed, as the readers' messages give it (io::ParseError's file,
// line and message; 0: no line, as for a file that cannot be opened).
struct InputError {
    std::string file;
    std::size_t line = 0;
    std::string reason;
};

// The error `e` raised while processing `input`: a ParseError's own file, line and message,
// any other error's text against `input`.
InputError inputErrorFrom(const std::exception& e, const std::string& input);

// Two runs of one well compared: by `compare`, or by `render` and `export` colouring the wall by
// the change (docs/formats.md, "Summary lines").
struct ComparedRuns {
    std::string file2;  // the other run (run 2)
    // The comparison's figures; its per-depth sections may have been left out.
    std::shared_ptr<const reconstruction::RunComparison> comparison;
    std::size_t sections = 0;  // depths of the overlap
    // What the wall's colour shows ("A minus B, equivalent diameter"); empty: no wall drawn.
    std::string wallColour;
};

// One line of a --summary file: what a verb made of one input (docs/formats.md, "Summary
// lines"). Fields a verb does not measure stay unset and are left out of the line.
struct InputSummary {
    std::string file;
    std::string verb;
    std::optional<InputError> error;  // set: status "failed"
    std::vector<std::string> outputs;
    std::optional<std::size_t> rows;
    std::optional<double> top_m, bottom_m;
    std::map<std::string, std::size_t> classes;  // report: sections per class
    std::optional<std::size_t> zones;
    std::map<std::string, std::size_t> zonesByClass;
    std::optional<reconstruction::HoleVolume> volume;
    // The breakouts' azimuths (null where unknown: no orientation) and how many sections had
    // no orientation.
    std::optional<reconstruction::BreakoutSummary> breakouts;
    std::size_t unorientedSections = 0;
    std::vector<reconstruction::CasingCheck> casing;          // the calibration check per string
    std::vector<reconstruction::NoDataInterval> armsNotOpen;  // sections no_data: arms not open
    std::optional<ComparedRuns> compared;
    std::size_t warningCount = 0;
    std::vector<std::string> warnings;  // the first kKeptWarnings, formatted as printed
    double seconds = 0.0;
    double peakRss_mb = 0.0;

    static constexpr std::size_t kKeptWarnings = 20;
    // Records the warnings of `diagnostics` (the count and the first messages).
    void addWarnings(const io::Diagnostics& diagnostics);
    // Records the report's counts: rows, depths, classes, zones, volumes.
    void addAnalysis(const reconstruction::WellAnalysis& analysis);
};

nlohmann::ordered_json toJson(const InputSummary& summary);

// A --summary FILE.jsonl: one JSON object a line, written (and flushed) as each input ends,
// so a run that is stopped keeps the lines of the inputs it finished. No file: writes nothing.
class SummaryFile {
public:
    explicit SummaryFile(const std::string& path);  // "" for none; throws when it cannot open
    ~SummaryFile();
    SummaryFile(const SummaryFile&) = delete;
    SummaryFile& operator=(const SummaryFile&) = delete;
    void write(const InputSummary& summary);
    void write(const nlohmann::ordered_json& line);

private:
    std::FILE* m_file = nullptr;
    std::string m_path;
};

// Seconds since `start` of a steady clock, and the peak resident memory of this process
// (MiB), stamped on `summary`.
void stampCost(InputSummary& summary, double startSeconds);
// A steady clock in seconds, for stampCost.
double steadySeconds();

}  // namespace caliper3d::app

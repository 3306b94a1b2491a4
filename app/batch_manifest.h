#pragma once

#include <cstddef>
#include <istream>
#include <string>
#include <vector>

#include "app/well_option_table.h"

namespace caliper3d::app {

// One well of a batch manifest (docs/formats.md, "Batch manifests"). Paths are as resolved
// against the manifest's folder.
struct ManifestRow {
    std::size_t index = 0;  // among the data rows, from 0: batch --row, SLURM_ARRAY_TASK_ID
    std::size_t line = 0;   // of the manifest (a JSON manifest: 0)
    std::string file;
    std::vector<std::string> verbs;  // each run in turn on the file
    std::string output;              // a file, a folder ("out/") or a pattern; empty: batch -o
    // The cells of the columns that are options of the table (app/well_option_table.h), by
    // option name; empty cells left out, paths resolved. The verb parses them.
    OptionTexts wellOptions;
    std::vector<std::string> options;  // further arguments for every verb of the row
    std::string problem;               // why the row cannot run; empty: it can
};

struct Manifest {
    std::string path;
    std::vector<ManifestRow> rows;
};

// The verbs a manifest row may run.
const std::vector<std::string>& batchVerbs();
// The manifest's columns (and JSON keys): file, verb, output, a column for each option of the
// table that has one, options.
const std::vector<std::string>& manifestColumns();

// Reads a CSV manifest (a header row naming the columns, then one well a row; '#' lines and
// blank lines skipped; fields with commas in double quotes) or a JSON one (a name ending
// .json: an array of objects with the same keys, or {"wells": [...]}). A row that cannot run
// (no file, an unknown verb, a field too many) keeps its place with its problem set. Throws
// io::ParseError for a manifest that cannot be read at all (no file, an unknown column).
Manifest readManifest(const std::string& path);
// The same from a stream; `path` names it in messages, places its relative paths and, by
// its extension, says whether it is JSON.
Manifest parseManifest(const std::string& path, std::istream& in);

// The arguments of "caliper3d VERB ..." for `row` (the verb not included), writing `output`
// (ignored by info) and the summary line to `summary`: the row's option cells the verb takes,
// then its further options.
std::vector<std::string> verbArguments(const ManifestRow& row, const std::string& verb,
                                       const std::string& output, const std::string& summary);

// Where `verb` writes for `row`: the row's output (a folder gets STEM.csv, .png or .iv),
// else `folder` (batch -o) the same way; empty for info. Throws std::invalid_argument when
// there is nowhere to write or a single file is named for several verbs.
std::string rowOutput(const ManifestRow& row, const std::string& verb, const std::string& folder);

}  // namespace caliper3d::app

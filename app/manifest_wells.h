#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "app/batch_manifest.h"

namespace caliper3d::app {

// One well of a batch manifest as the window opens it (caliper3d view --manifest): its file
// with the row's survey, wellhead and picks, and its options: the command line's, then the
// row's option cells and its further options over them. A row that cannot be opened keeps
// its place with `problem` set ("line 4: --bit-size: ...").
struct ManifestWell {
    std::size_t line = 0;  // of the manifest (a JSON manifest: 0)
    WellSource source;
    LoadOptions options;
    std::string problem;
    std::vector<std::string> ignored;  // options of the row for the batch's verbs, not a well's
};

// The wells of `manifest` in row order, each read with `base` (the command line's options)
// and its row's options. The rows' verbs and outputs are the batch's: the window opens every
// row's file whatever it runs. Of a row's further options ("options" column) the well options
// apply ("--bit-size 8.5in", "--survey=s.csv"); the verbs' own (report's --step) are listed
// in `ignored`.
std::vector<ManifestWell> manifestWells(const Manifest& manifest, const LoadOptions& base);

}  // namespace caliper3d::app

#include "support/column_text_reader.h"

#include "io/log_reader.h"
#include "io/parse_error.h"

namespace caliper3d::io {

namespace {

ReadOptions readOptions(const ColumnTextOptions& options) {
    ReadOptions r;
    r.armCount = options.armCount;
    r.depthUnit = options.depthUnit;
    r.radiusUnit = options.radiusUnit;
    r.allowRadiiOnly = options.allowRadiiOnly;
    r.rowStep_m = options.rowStep_m;
    return r;
}

SectionTable columnTextOnly(LoadedLog log, const std::string& name, Diagnostics* diagnostics) {
    if (log.info.format.rfind("column text", 0) != 0)
        throw ParseError(name, 1, 1, "expected column text, found " + log.info.format);
    if (diagnostics) {
        for (const Warning& w : log.info.diagnostics.warnings)
            if (diagnostics->warnings.size() < Diagnostics::kKeptMessages)
                diagnostics->warnings.push_back(w);
        diagnostics->warningCount += log.info.diagnostics.warningCount;
    }
    return std::move(log.table);
}

}  // namespace

// The one column-text reader is the streaming one (io/log_stream.cpp); these
// read a whole file or text with the reference layout's options.
SectionTable parseColumnText(const std::string& text, const std::string& name,
                             const ColumnTextOptions& options, Diagnostics* diagnostics) {
    return columnTextOnly(loadCaliperText(text, name, readOptions(options)), name, diagnostics);
}

SectionTable readColumnText(const std::string& path, const ColumnTextOptions& options,
                            Diagnostics* diagnostics) {
    return columnTextOnly(loadCaliperLog(path, readOptions(options)), path, diagnostics);
}

}  // namespace caliper3d::io

#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "io/diagnostics.h"

namespace caliper3d::io {

// One header line "MNEM.UNIT  VALUE : DESCRIPTION" of a LAS section.
struct LasItem {
    std::string mnemonic;
    std::string unit;
    std::string value;
    std::string description;
    std::size_t line = 0;  // 1-based
};

// Where the data of a LAS file lie, and everything above them. Header
// parsing is separate from data parsing (the data are read afterwards, in
// one pass, possibly streamed).
struct LasHeader {
    std::string file;
    double version = 2.0;
    bool wrap = false;
    char delimiter = ' ';  // ' ' = runs of spaces or tabs; ',' for LAS 3.0 DLM COMMA; '\t' for TAB
    bool hasNull = false;
    double null = -999.25;
    // ~P "NULLS. DECLARED": the file says that only its NULL value marks a
    // missing reading (caliper3d's writer says so, for an exact round trip);
    // read with NullPolicy::Declared whatever the reader's policy.
    bool onlyDeclaredNull = false;
    std::vector<LasItem> versionItems;
    std::vector<LasItem> well;
    std::vector<LasItem> curves;         // ~C, or ~Log_Definition in LAS 3.0
    std::vector<LasItem> parameters;     // ~P, or ~Log_Parameter
    std::string other;                   // ~O text
    std::vector<std::string> dataNames;  // names after "~A" on its own line, if any

    bool hasData = false;
    std::size_t dataBegin = 0;      // byte offset of the first line after the ~A line
    std::size_t dataEnd = 0;        // byte offset where the data end (next section or end of text)
    std::size_t dataFirstLine = 0;  // 1-based line number at dataBegin

    const LasItem* wellItem(std::string_view mnemonic) const;
    const LasItem* parameter(std::string_view mnemonic) const;
};

// Parses every section of a LAS 1.2, 2.0 or 3.0 file held in `text`.
// Throws ParseError naming file and line for a file that is not LAS, is
// UTF-16, lacks ~V or ~C, or has a malformed header line; records lenient
// repairs (duplicated sections, unusual order, unknown sections) in `diagnostics`.
LasHeader parseLasHeader(std::string_view text, const std::string& file, Diagnostics* diagnostics);

// True for a section title that starts the log data: "~A ...", "~ASCII",
// "~Log_Data | Log_Definition" (the line trimmed, starting with '~').
bool isLasDataTitle(std::string_view title);

// Splits one header line into its parts (exposed for tests). Returns false
// for a line that has no '.' separating mnemonic and unit. `curveLine`: a ~C
// line, where a mnemonic may end in a dot ("Cond..MS/M").
bool splitLasItem(std::string_view line, LasItem& item, bool curveLine = true);

}  // namespace caliper3d::io

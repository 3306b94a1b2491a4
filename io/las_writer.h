#pragma once

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "io/section_table.h"

namespace caliper3d::io {

// A ~Parameter line: " MNEM.UNIT  VALUE : DESCRIPTION".
struct LasParameter {
    std::string mnemonic;
    std::string unit;
    std::string value;
    std::string description;
};

struct LasWriteOptions {
    std::string wellName = "CALIPER3D";
    double null = -999.25;  // written for NaN; writeLas moves it to the first of -999.25,
                            //   -9999.25, -99999.25, ... that no true value equals
    std::vector<LasParameter> parameters;  // ~Parameter section, when not empty
    std::string other;                     // ~Other section (free text), when not empty
};

// One data column: `rows` values starting at `values`, `stride` apart (the
// radii of a section table are row-major, so arm k of row r is at k + r*N).
struct LasColumn {
    std::string mnemonic;
    std::string unit;
    std::string description;
    const double* values = nullptr;
    std::size_t stride = 1;
    int decimals = -1;  // fixed decimals; -1: the shortest text that reads back exactly
};

// Writes LAS 2.0, one line per row, the first column the depth index (its
// unit gives STRT/STOP/STEP's; STEP is the nominal step, or 0 when the step
// varies, as LAS 2.0 asks). Values are written with the column's fixed
// decimals, or as the shortest text that reads back to the same double; NaN is
// written as the null value.
void writeLasColumns(std::ostream& out, std::size_t rows, const std::vector<LasColumn>& columns,
                     const LasWriteOptions& options = {});

// Writes a section table as LAS 2.0: DEPT (M), R1..RN (MM, radii), then the
// optional P1AZ, DEVI, HAZI, RB (DEG), BS (MM) and every extra curve in its
// own unit, so that readCaliperLog returns exactly the table written (round
// trip): the NULL value is one no true value equals, and ~P says
// "NULLS. DECLARED" (only NULL marks a missing value, so a true 9999 is not
// taken for a common null). Throws std::invalid_argument for a depth that is
// not finite.
void writeLas(std::ostream& out, const SectionTable& table, const LasWriteOptions& options = {});
// The same to a file, whole or not at all (io/atomic_output.h); throws std::runtime_error naming
// the file when it cannot be written.
void writeLasFile(const std::string& path, const SectionTable& table,
                  const LasWriteOptions& options = {});

}  // namespace caliper3d::io

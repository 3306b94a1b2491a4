#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/casing_string.h"
#include "io/diagnostics.h"
#include "io/las_header.h"
#include "io/las_writer.h"

namespace caliper3d::io {

// The nominal inner diameter of a casing of outer diameter `size_mm` and nominal linear mass
// `weight_kgPerM`, from the API 5CT nominal wall thickness (API Specification 5CT / ISO 11960,
// casing list: ID = D - 2t) for the common size and weight pairs of its table (size within
// 0.5 mm, weight within 1.5 %); NaN for a pair not in the table (docs/analysis.md, "Cased hole").
double nominalCasingId_mm(double size_mm, double weight_kgPerM);

// The casing program of a LAS header (docs/formats.md, "Casing program"): the shoe from CSGL or
// CBLO (logger), else CSGD or CBDR (driller); the size from CSGS or CSIZ; the weight from CSGW;
// the type from CSGT. One string (the header's current casing); empty when no shoe depth is
// given. An item that cannot be read (no unit, not a number) is skipped with a warning naming
// its line; a size without a shoe depth is warned about and not used.
// Then the numbered strings a spliced log writes (casingParameters): CSGL[1], CSGS[1], CSGW[1],
// CSID[1] (inner diameter), CSGT[1] and CSRG[1] (the log depths it holds over, "FROM, TO"),
// then [2], ... up to the first number without a shoe.
std::vector<CasingString> readCasingProgram(const LasHeader& header, const std::string& file,
                                            Diagnostics* diagnostics);

// The ~Parameter lines of a casing program, read back by readCasingProgram to the same strings
// (their sources aside): the numbered form above, one number per string, each with its shoe,
// size, weight, inner diameter, type and depths (when both ends are known) where known.
std::vector<LasParameter> casingParameters(const std::vector<CasingString>& program);

// One --casing value "BOTTOM,SIZE[,WEIGHT|ID]": the shoe's measured depth in metres; the outer
// diameter as a length ("7in", "177.8mm"; a bare number is inches); then either the nominal
// weight with its unit ("17lb/ft", "25.3kg/m") or the inner diameter as a length with its unit
// ("6.538in", "166.1mm"). nullopt, with `error` saying what was expected, when malformed.
std::optional<CasingString> parseCasingSpec(std::string_view text, std::string& error);
// The text parseCasingSpec reads back to `casing` (its source aside).
std::string casingSpecText(const CasingString& casing);

// "177.8 mm (7.000 in), 25.3 kg/m, to 88.30 m; nominal ID 166.07 mm (API 5CT)" (what info and
// the report print; says "inner diameter unknown" when it is).
std::string describeCasing(const CasingString& casing);

// The casing string a section at measured depth `md_m` is inside: the narrowest one whose shoe
// is at or below it, of those that hold at md_m (CasingString::appliesFrom_m, appliesTo_m);
// nullptr in open hole.
const CasingString* casingAt(const std::vector<CasingString>& program, double md_m);

}  // namespace caliper3d::io

#pragma once

#include <optional>
#include <string_view>

namespace caliper3d::io {

// Length units met in caliper logs. Internally depths are metres and radii millimetres.
enum class LengthUnit { Metre, Foot, Inch, Millimetre, Centimetre };

// Factor that converts a value in `unit` to millimetres.
double toMillimetres(LengthUnit unit);
// Factor that converts a value in `unit` to metres.
double toMetres(LengthUnit unit);

// Parses a unit name as written in log headers and on the command line
// ("m", "M", "ft", "F", "in", "IN", "mm", "cm", ...). Empty when unknown.
std::optional<LengthUnit> parseLengthUnit(std::string_view text);

std::string_view unitName(LengthUnit unit);

}  // namespace caliper3d::io

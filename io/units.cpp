#include "io/units.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace caliper3d::io {

double toMillimetres(LengthUnit unit) {
    switch (unit) {
        case LengthUnit::Metre:
            return 1000.0;
        case LengthUnit::Foot:
            return 304.8;
        case LengthUnit::Inch:
            return 25.4;
        case LengthUnit::Millimetre:
            return 1.0;
        case LengthUnit::Centimetre:
            return 10.0;
    }
    return 1.0;
}

double toMetres(LengthUnit unit) {
    return toMillimetres(unit) / 1000.0;
}

std::optional<LengthUnit> parseLengthUnit(std::string_view text) {
    std::string s(text);
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (s == "m" || s == "metre" || s == "meter" || s == "metres" || s == "meters")
        return LengthUnit::Metre;
    if (s == "ft" || s == "f" || s == "feet" || s == "foot") return LengthUnit::Foot;
    if (s == "in" || s == "inch" || s == "inches") return LengthUnit::Inch;
    if (s == "mm" || s == "millimetre" || s == "millimeter") return LengthUnit::Millimetre;
    if (s == "cm" || s == "centimetre" || s == "centimeter") return LengthUnit::Centimetre;
    return std::nullopt;
}

std::string_view unitName(LengthUnit unit) {
    switch (unit) {
        case LengthUnit::Metre:
            return "m";
        case LengthUnit::Foot:
            return "ft";
        case LengthUnit::Inch:
            return "in";
        case LengthUnit::Millimetre:
            return "mm";
        case LengthUnit::Centimetre:
            return "cm";
    }
    return "?";
}

}  // namespace caliper3d::io

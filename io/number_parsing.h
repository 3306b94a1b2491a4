#pragma once

#include <string_view>

namespace caliper3d::io {

// Parses a whole token as a double with std::from_chars (locale-independent).
// A single comma is read as a decimal mark ("359,98610"), as written by tools
// on a Portuguese or Brazilian locale. Returns false if the token is not
// entirely one finite or infinite number.
bool parseNumber(std::string_view token, double& value);

}  // namespace caliper3d::io

#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "vec3.h"

namespace rtvk {

// Parses an aspect ratio written as "W:H" (16:9) or as a decimal (1.5). Both parts must be
// finite and > 0. Throws usage_error naming the flag and the text.
double parse_aspect(const std::string& text, const std::string& flag = "--aspect");

// Parses three finite numbers separated by commas ("13,2,3"). Throws usage_error naming the flag
// and the text.
vec3 parse_vec3(const std::string& text, const std::string& flag);

// Parses from `least` to `most` finite numbers separated by commas ("500,500,319.5,239.5").
// Throws usage_error naming the flag, the text and what was expected (`what`).
std::vector<double> parse_numbers(const std::string& text, const std::string& flag,
                                  std::size_t least, std::size_t most, const std::string& what);

}  // namespace rtvk

/// @file Finds functions (at namespace or class scope) longer than a limit, by brace matching.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace silva::house {

/// One function longer than the limit.
struct LongFunction {
  int line = 0;        ///< 1-based line of the function's opening brace
  int lines = 0;       ///< lines from the opening brace's line to the closing brace's, inclusive
  std::string header;  ///< the declaration before the brace, whitespace collapsed
};

/// True when the header text before a '{' at namespace or class scope opens a function body:
/// it has a ')' and is no control statement, lambda, namespace, class, enum or `= {` initializer.
bool opens_function(std::string_view header);

/// True when more than half of `body` lines are data rows (starting with '{', '"' or a number).
bool is_table(const std::vector<std::string>& body);

/// The functions at namespace or class scope of `source` longer than `max_lines` lines, tables aside.
std::vector<LongFunction> find_long_functions(std::string_view source, int max_lines);

}  // namespace silva::house

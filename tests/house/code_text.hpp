/// @file C++ source reduced to its code: comments, literal contents and preprocessor lines blanked.
#pragma once

#include <string>
#include <string_view>

namespace silva::house {

/// `source` with comments, the contents of string and character literals, and preprocessor
/// lines replaced by spaces; quotes and line breaks stay, so offsets and line numbers match.
std::string code_only(std::string_view source);

}  // namespace silva::house

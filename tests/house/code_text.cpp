#include "code_text.hpp"

#include <algorithm>
#include <cctype>

namespace silva::house {
namespace {

enum class State { code, line_comment, block_comment, string, character };

// Blanks comments and literal contents (the first pass of code_only).
std::string without_comments_and_literals(std::string_view s) {
  std::string out(s);
  State st = State::code;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    const char next = i + 1 < s.size() ? s[i + 1] : '\0';
    switch (st) {
      case State::code:
        if (c == '/' && next == '/') {
          st = State::line_comment;
          out[i] = ' ';
        } else if (c == '/' && next == '*') {
          st = State::block_comment;
          out[i] = out[i + 1] = ' ';
          ++i;
        } else if (c == '"') {
          st = State::string;
        } else if (c == '\'' && !(i > 0 && std::isxdigit(static_cast<unsigned char>(s[i - 1])))) {
          st = State::character;  // after a digit, ' is a digit separator (1'000)
        }
        break;
      case State::line_comment:
        if (c == '\n') st = State::code; else out[i] = ' ';
        break;
      case State::block_comment:
        if (c == '*' && next == '/') {
          out[i] = out[i + 1] = ' ';
          ++i;
          st = State::code;
        } else if (c != '\n') {
          out[i] = ' ';
        }
        break;
      case State::string:
      case State::character:
        if (c == '\\') {
          out[i] = ' ';
          if (next != '\n' && next != '\0') out[++i] = ' ';
        } else if ((st == State::string && c == '"') || (st == State::character && c == '\'') || c == '\n') {
          st = State::code;  // a line break ends an unterminated literal
        } else {
          out[i] = ' ';
        }
        break;
    }
  }
  return out;
}

}  // namespace

std::string code_only(std::string_view source) {
  std::string out = without_comments_and_literals(source);
  bool in_directive = false;
  std::size_t start = 0;
  while (start < out.size()) {
    const std::size_t end = std::min(out.find('\n', start), out.size());
    const std::size_t first = out.find_first_not_of(" \t\r", start);
    if (first < end && out[first] == '#') in_directive = true;
    if (in_directive) {
      const std::size_t last = out.find_last_not_of(" \t\r", end == 0 ? 0 : end - 1);
      const bool continues = last != std::string::npos && last >= start && last < end && out[last] == '\\';
      for (std::size_t i = start; i < end; ++i) out[i] = ' ';
      in_directive = continues;
    }
    start = end + 1;
  }
  return out;
}

}  // namespace silva::house

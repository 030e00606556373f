#include "cmake_calls.hpp"

#include <algorithm>
#include <cctype>

namespace silva::house {
namespace {

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

/// `text` with every comment, from a '#' outside quotes to the end of its line, removed.
std::string without_comments(std::string_view text) {
  std::string out;
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (quoted && text[i] == '\\' && i + 1 < text.size()) {
      out += text.substr(i++, 2);
      continue;
    }
    if (text[i] == '"') quoted = !quoted;
    if (text[i] == '#' && !quoted) {
      i = std::min(text.find('\n', i), text.size()) - 1;
      continue;
    }
    out += text[i];
  }
  return out;
}

/// The arguments from `at` (just past an opening parenthesis) to its match; `at` ends past the match.
std::vector<std::string> arguments(const std::string& code, std::size_t& at) {
  std::vector<std::string> args;
  std::string arg;
  int depth = 1;
  bool quoted = false;
  for (; at < code.size(); ++at) {
    const char c = code[at];
    if (quoted && c == '\\' && at + 1 < code.size()) {
      arg += code[++at];
    } else if (c == '"') {
      quoted = !quoted;
    } else if (quoted || !is_space(c)) {
      if (!quoted && c == ')' && --depth == 0) break;
      if (!quoted && c == '(') ++depth;
      arg += c;
    } else if (!arg.empty()) {
      args.push_back(std::move(arg));
      arg.clear();
    }
  }
  if (!arg.empty()) args.push_back(std::move(arg));
  at = std::min(at + 1, code.size());
  return args;
}

}  // namespace

std::vector<CMakeCall> cmake_calls(std::string_view text) {
  const std::string code = without_comments(text);
  std::vector<CMakeCall> calls;
  std::size_t at = 0;
  while (at < code.size()) {
    if (!is_word_char(code[at])) {
      ++at;
      continue;
    }
    const std::size_t start = at;
    while (at < code.size() && is_word_char(code[at])) ++at;
    std::string name = code.substr(start, at - start);
    while (at < code.size() && (code[at] == ' ' || code[at] == '\t')) ++at;
    if (at == code.size() || code[at] != '(') continue;
    ++at;
    std::vector<std::string> args = arguments(code, at);
    calls.push_back({std::move(name), std::move(args)});
  }
  return calls;
}

}  // namespace silva::house

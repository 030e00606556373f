#include "function_length.hpp"

#include <algorithm>
#include <cctype>
#include <regex>

#include "code_text.hpp"
#include "source_tree.hpp"

namespace silva::house {
namespace {

// What a '{' opened: a scope that may hold functions (namespace, class), a function body, or
// anything else (blocks, initializers, enums).
enum class Scope { outer, function, other };

struct Open {
  Scope kind;
  int line;
  std::string header;
};

std::string collapsed(std::string_view s) {
  std::string out;
  for (const char c : s) {
    const bool space = std::isspace(static_cast<unsigned char>(c)) != 0;
    if (space && (out.empty() || out.back() == ' ')) continue;
    out += space ? ' ' : c;
  }
  if (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

// The header without a leading access specifier ("public:").
std::string without_access(const std::string& h) {
  static const std::regex kAccess(R"(^(public|private|protected)\s*:\s*)");
  return std::regex_replace(h, kAccess, "");
}

// The header without a leading access specifier and `template <...>`.
std::string declaration_part(std::string h) {
  h = without_access(h);
  if (h.rfind("template", 0) == 0) {
    const std::size_t open = h.find('<');
    int depth = 0;
    for (std::size_t i = open; open != std::string::npos && i < h.size(); ++i) {
      depth += h[i] == '<' ? 1 : h[i] == '>' ? -1 : 0;
      if (depth == 0) return collapsed(h.substr(i + 1));
    }
  }
  return h;
}

Scope classify(std::string_view raw_header) {
  static const std::regex kOuter(R"(^(namespace|extern|inline namespace)\b)");
  static const std::regex kClass(R"(^(struct|class|union)\b)");
  static const std::regex kControl(R"(^(if|for|while|switch|catch|do|else|try|return)\b)");
  static const std::regex kOperatorBrackets(R"(operator\s*(\[\s*\]|\(\s*\)))");
  static const std::regex kLambda(R"(\[[^\]]*\]\s*(\(|\{|mutable|->|$))");
  const std::string h = collapsed(raw_header);
  if (std::regex_search(h, kOuter)) return Scope::outer;
  const std::string decl = declaration_part(h);
  if (std::regex_search(decl, kClass)) return Scope::outer;
  if (decl.empty() || decl.back() == '=' || decl.rfind("enum", 0) == 0) return Scope::other;
  if (decl.find(')') == std::string::npos || std::regex_search(decl, kControl)) return Scope::other;
  if (std::regex_search(std::regex_replace(decl, kOperatorBrackets, "operator"), kLambda)) return Scope::other;
  return Scope::function;
}

bool is_data_row(const std::string& line) {
  const std::size_t b = line.find_first_not_of(" \t");
  if (b == std::string::npos) return false;
  const char c = line[b];
  const char next = b + 1 < line.size() ? line[b + 1] : '\0';
  if (c == '{') return line.find_first_not_of(" \t\r", b + 1) != std::string::npos;  // not a bare '{'
  if (c == '"' || std::isdigit(static_cast<unsigned char>(c))) return true;
  return (c == '-' || c == '+' || c == '.') && std::isdigit(static_cast<unsigned char>(next));
}

}  // namespace

bool opens_function(std::string_view header) { return classify(header) == Scope::function; }

bool is_table(const std::vector<std::string>& body) {
  std::size_t rows = 0;
  for (const std::string& line : body) rows += is_data_row(line) ? 1 : 0;
  return rows * 2 > body.size();
}

std::vector<LongFunction> find_long_functions(std::string_view source, int max_lines) {
  const std::string code = code_only(source);
  const std::vector<std::string> lines = split_lines(source);
  std::vector<LongFunction> found;
  std::vector<Open> stack;
  std::string header;  // the code since the last ';', '{' or '}'
  int line = 1;
  for (const char c : code) {
    if (c == '\n') {
      ++line;
      header += ' ';
    } else if (c == '{') {
      const bool at_outer = std::all_of(stack.begin(), stack.end(), [](const Open& o) { return o.kind == Scope::outer; });
      stack.push_back({at_outer ? classify(header) : Scope::other, line, without_access(collapsed(header))});
      header.clear();
    } else if (c == '}') {
      if (!stack.empty()) {
        const Open o = stack.back();
        stack.pop_back();
        const int length = line - o.line + 1;
        if (o.kind == Scope::function && length > max_lines &&
            !is_table(std::vector<std::string>(lines.begin() + o.line, lines.begin() + line - 1))) {
          found.push_back({o.line, length, o.header});
        }
      }
      header.clear();
    } else if (c == ';') {
      header.clear();
    } else {
      header += c;
    }
  }
  return found;
}

}  // namespace silva::house

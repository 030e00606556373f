// Known answers for the function-length detector and the code reducer it stands on.
#include <gtest/gtest.h>

#include "code_text.hpp"
#include "function_length.hpp"

namespace silva::house {
namespace {

// A function of exactly `lines` lines: its header line, the body, its closing brace.
std::string function_of(int lines, const std::string& name = "f") {
  std::string s = "int " + name + "(int x) {\n";
  for (int i = 0; i < lines - 2; ++i) s += "  x += 1;\n";
  return s + "}\n";
}

TEST(FunctionLength, A90LineFunctionIsFound) {
  const auto found = find_long_functions(function_of(90), 80);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].line, 1);
  EXPECT_EQ(found[0].lines, 90);
  EXPECT_EQ(found[0].header, "int f(int x)");
}

TEST(FunctionLength, An80LineFunctionIsNot) { EXPECT_TRUE(find_long_functions(function_of(80), 80).empty()); }

TEST(FunctionLength, A100LineTableIsAllowed) {
  std::string s = "const Row* rows() {\n  static const Row kRows[] = {\n";
  for (int i = 0; i < 95; ++i) s += "      {" + std::to_string(i) + ", \"name\", 0.5f},\n";
  s += "  };\n  return kRows;\n}\n";
  EXPECT_TRUE(find_long_functions(s, 80).empty());
  EXPECT_EQ(find_long_functions(s, 10).size(), 0u);
}

TEST(FunctionLength, FunctionsInNamespacesAndClassesAreMeasured) {
  const std::string s = "namespace a {\nnamespace {\nstruct S {\n public:\n" + function_of(90, "g") + "};\n}\n}\n" +
                        "template <class T>\n" + function_of(85, "h");
  const auto found = find_long_functions(s, 80);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].header, "int g(int x)");
  EXPECT_EQ(found[0].line, 5);
  EXPECT_EQ(found[1].lines, 85);
}

TEST(FunctionLength, BracesInCommentsAndLiteralsDoNotCount) {
  std::string s = function_of(90);
  s.insert(s.find('\n') + 1, "  // }\n  const char* t = \"}}\"; char c = '}'; /* { */ int n = 1'000;\n");
  const auto found = find_long_functions(s, 80);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].lines, 92);  // the two inserted lines count
}

TEST(FunctionLength, OnlyFunctionHeadersOpenFunctions) {
  EXPECT_TRUE(opens_function("int f(int x) const"));
  EXPECT_TRUE(opens_function("Foo::Foo(int x) : a_(x), b_(2)"));
  EXPECT_TRUE(opens_function("T& operator[](std::size_t i)"));
  EXPECT_TRUE(opens_function("template <class T> void f(T t) noexcept"));
  EXPECT_FALSE(opens_function("namespace silva::render"));
  EXPECT_FALSE(opens_function("struct Row"));
  EXPECT_FALSE(opens_function("enum class Kind : int"));
  EXPECT_FALSE(opens_function("static const int kTable[] ="));
  EXPECT_FALSE(opens_function("const auto f = [](int x)"));
  EXPECT_FALSE(opens_function("if (x > 0)"));
  EXPECT_FALSE(opens_function("std::array<int, 3> values"));
}

TEST(CodeText, KeepsLineBreaksAndBlanksCommentsLiteralsAndDirectives) {
  EXPECT_EQ(code_only("#include \"a/b.hpp\"\nint x = 1; // }\n"), "                  \nint x = 1;     \n");
  EXPECT_EQ(code_only("f(\"{\\\"\", '}');"), "f(\"   \", ' ');");
  EXPECT_EQ(code_only("a /* {\n} */ b"), "a     \n     b");
}

}  // namespace
}  // namespace silva::house

// Known answers for reading CMake calls.
#include <gtest/gtest.h>

#include "cmake_calls.hpp"

namespace silva::house {
namespace {

TEST(CMakeCalls, CallsSpanLinesAndSkipComments) {
  const std::vector<CMakeCall> calls = cmake_calls(R"(# silva_library(silva_x x silva_app)
silva_library(silva_io io silva_core  # the base
              "TBB::tbb" $<$<CXX_COMPILER_ID:GNU>:-Wno-x>)
if((A) OR B)
set_source_files_properties(x PROPERTIES COMPILE_DEFINITIONS "V=\"${V}\";W=1")
target_link_libraries (silva_web PRIVATE PkgConfig::HTTPLIB))");
  ASSERT_EQ(calls.size(), 4u);
  EXPECT_EQ(calls[0].command, "silva_library");
  EXPECT_EQ(calls[0].args,
            (std::vector<std::string>{"silva_io", "io", "silva_core", "TBB::tbb", "$<$<CXX_COMPILER_ID:GNU>:-Wno-x>"}));
  EXPECT_EQ(calls[1].args, (std::vector<std::string>{"(A)", "OR", "B"}));
  EXPECT_EQ(calls[2].args.back(), "V=\"${V}\";W=1");
  EXPECT_EQ(calls[3].command, "target_link_libraries");
  EXPECT_EQ(calls[3].args, (std::vector<std::string>{"silva_web", "PRIVATE", "PkgConfig::HTTPLIB"}));
}

}  // namespace
}  // namespace silva::house

#include "io/output_types.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace silva::io {
namespace {

TEST(OutputTypes, NamesRoundTrip) {
  std::vector<std::string> names;
  for (int t = 0; t < kOutputTypeCount; ++t) names.push_back(output_type_name(OutputType(t)));
  EXPECT_EQ(names, (std::vector<std::string>{"rgb", "semantic", "semantic_color", "instance", "depth", "depth_exr",
                                             "depth_preview", "normal", "lidar"}));
  const OutputSelection s = OutputSelection::from_names(names);
  for (int t = 0; t < kOutputTypeCount; ++t) EXPECT_TRUE(s.has(OutputType(t)));
}

TEST(OutputTypes, UnknownOrRepeatedNameIsInputError) {
  try {
    OutputSelection::from_names({"rgb", "depthh"});
    FAIL();
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("output.types"), std::string::npos);
    EXPECT_NE(m.find("depthh"), std::string::npos);
    EXPECT_NE(m.find("depth_preview"), std::string::npos);
  }
  EXPECT_THROW(OutputSelection::from_names({"rgb", "rgb"}), InputError);
}

}  // namespace
}  // namespace silva::io

#include "pipeline/config/edit_distance.hpp"

#include <gtest/gtest.h>

namespace silva::pipeline {
namespace {

TEST(EditDistance, KnownAnswers) {
  EXPECT_EQ(edit_distance("", ""), 0u);
  EXPECT_EQ(edit_distance("abc", ""), 3u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("fov_deg", "fovdeg"), 1u);
  EXPECT_EQ(edit_distance("flaw", "lawn"), 2u);
}

TEST(EditDistance, IsSymmetric) {
  EXPECT_EQ(edit_distance("camera.near", "camra.nera"), edit_distance("camra.nera", "camera.near"));
}

}  // namespace
}  // namespace silva::pipeline

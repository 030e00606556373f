#include "io/tum_trajectory_file.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"

namespace silva::io {
namespace {

/// The InputError message of parsing `text`, or "" when it parses.
std::string error_of(const std::string& text) {
  try {
    parse_tum_trajectory(text, "walk.txt");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(TumTrajectoryFile, ReadsPosesSkippingCommentsAndBlankLines) {
  const auto poses = parse_tum_trajectory(
      "# timestamp tx ty tz qx qy qz qw\n\n0.5 1 2 3 0 0 0 1\n  1.0 4 5 6 0 0 0.7071067811865476 0.7071067811865476\r\n",
      "walk.txt");
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_DOUBLE_EQ(poses[0].t, 0.5);
  EXPECT_EQ(poses[1].position, Vec3d(4, 5, 6));
  EXPECT_TRUE(poses[0].rotation.isApprox(Mat3d::Identity()));
  EXPECT_NEAR(poses[1].rotation(1, 0), 1.0, 1e-12);  // 90 degrees about z: x turns to y
}

TEST(TumTrajectoryFile, RefusesTimesThatDoNotIncrease) {
  const std::string e = error_of("0 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n");
  EXPECT_NE(e.find("walk.txt: line 3"), std::string::npos) << e;
  EXPECT_NE(e.find("strictly increase"), std::string::npos) << e;
}

TEST(TumTrajectoryFile, RefusesQuaternionsThatAreNotUnit) {
  const std::string e = error_of("0 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 2\n");
  EXPECT_NE(e.find("line 2"), std::string::npos) << e;
  EXPECT_NE(e.find("norm 2"), std::string::npos) << e;
}

TEST(TumTrajectoryFile, RefusesMalformedLinesAndShortOrOutOfWorldTrajectories) {
  EXPECT_NE(error_of("0 0 0 0 0 0 1\n").find("8 finite numbers"), std::string::npos);
  EXPECT_NE(error_of("0 0 0 0 0 0 0 1 9\n").find("found more"), std::string::npos);
  EXPECT_NE(error_of("0 nan 0 0 0 0 0 1\n").find("8 finite numbers"), std::string::npos);
  EXPECT_NE(error_of("# only a comment\n0 0 0 0 0 0 0 1\n").find("at least 2 poses"), std::string::npos);
  EXPECT_NE(error_of("0 0 0 0 0 0 0 1\n0.01 0 0 0 0 0 0 1\n").find("spans"), std::string::npos);
  EXPECT_NE(error_of("0 0 0 0 0 0 0 1\n1 2e5 0 0 0 0 0 1\n").find("outside the world"), std::string::npos);
  EXPECT_EQ(error_of("0 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 1.0004\n"), "");  // within the tolerance
}

}  // namespace
}  // namespace silva::io

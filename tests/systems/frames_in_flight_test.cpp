#include <gtest/gtest.h>

#include "systems/write_dataset.hpp"

namespace silva::systems {
namespace {

TEST(FramesInFlight, OneThreadWritesEachFrameBeforeTheNextTwoKeepTwoAndMoreThreadsKeepMoreFramesUpToTheCap) {
  EXPECT_EQ(frames_in_flight(0), 1u);
  EXPECT_EQ(frames_in_flight(1), 1u);
  EXPECT_EQ(frames_in_flight(2), 2u);
  EXPECT_EQ(frames_in_flight(3), 3u);
  EXPECT_EQ(frames_in_flight(5), 3u);
  EXPECT_EQ(frames_in_flight(6), 4u);
  EXPECT_EQ(frames_in_flight(10), 5u);
  EXPECT_EQ(frames_in_flight(16), 5u);
  EXPECT_EQ(frames_in_flight(256), kMaxFramesInFlight);
}

}  // namespace
}  // namespace silva::systems

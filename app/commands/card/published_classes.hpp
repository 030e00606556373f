#pragma once
/// @file Published class distributions of real off-road datasets, with their sources, that the dataset card
/// sets beside Silva's. Only numbers a source states are here (none read off a chart).
#include <cstdint>
#include <string>
#include <vector>

namespace silva::app {

/// One class of a published distribution.
struct PublishedClass {
  std::string name;     ///< The dataset's class name.
  uint64_t count = 0;   ///< Points (or pixels) of that class, as published.
};

/// A real dataset's class distribution and where it is published.
struct PublishedDistribution {
  std::string dataset;                  ///< e.g. "RELLIS-3D".
  std::string unit;                     ///< What is counted, e.g. "LiDAR points".
  std::string source;                   ///< Citation: paper, repository, file and commit.
  std::string unlabelled;               ///< The class name that means "not labelled" (left out of shares).
  std::vector<PublishedClass> classes;  ///< In the source's order.
};

/// RELLIS-3D (Jiang et al., ICRA 2021): LiDAR points per class of its SemanticKITTI-form point labels, the
/// `content:` table of the dataset's official label config.
const PublishedDistribution& rellis3d_lidar_points();

}  // namespace silva::app

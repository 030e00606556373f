#include "app/commands/card/published_classes.hpp"

namespace silva::app {

const PublishedDistribution& rellis3d_lidar_points() {
  static const PublishedDistribution d{
      "RELLIS-3D",
      "LiDAR points",
      "P. Jiang, P. Osteen, M. Wigness, S. Saripalli, \"RELLIS-3D Dataset: Data, Benchmarks and Analysis\", "
      "ICRA 2021; point counts from the `content:` table of benchmarks/SalsaNext/train/tasks/semantic/config/"
      "labels/rellis.yaml in github.com/unmannedlab/RELLIS-3D (commit 103ec706c23b8da05e096a3ea160a94eb0c8f6f9)",
      "void",
      {{"void", 447156890}, {"dirt", 0},          {"grass", 261005182}, {"tree", 107172982}, {"pole", 22852},
       {"water", 224173},   {"sky", 0},           {"vehicle", 111345},  {"object", 2},         {"asphalt", 479},
       {"building", 10},    {"log", 554091},      {"person", 10626325}, {"fence", 1588416},    {"bush", 168764964},
       {"concrete", 10944799}, {"barrier", 3502156}, {"puddle", 1493276}, {"mud", 5798200},   {"rubble", 3395458}}};
  return d;
}

}  // namespace silva::app

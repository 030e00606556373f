// `silva view` without a browser: the page's config edits, the views, and captures numbered in the pose file.
#include <gtest/gtest.h>

#include "app/commands/view/view_explorer.hpp"
#include "core/error.hpp"
#include "io/pose_file.hpp"
#include "io/run_lock.hpp"
#include "silva_process.hpp"

namespace silva::app {
namespace {

namespace fs = std::filesystem;

/// The tiny world of the CLI tests, writing into `out`.
ConfigSources tiny_sources(const fs::path& out) {
  ConfigSources s;
  s.seed = "21";
  s.overrides = {"output.dir=" + out.string(), "output.resolution=64x48",         "world.extent=128",
                 "world.render_distance=48",   "trail.control_points=6",          "camera.far=40",
                 "output.types=[\"semantic\",\"depth\"]"};
  return s;
}

TEST(ViewConfig, PageEditsGoThroughTheCliChecks) {
  const ConfigSources sources = tiny_sources("unused");
  EXPECT_EQ(load_view_config(sources, {std::string("12"), {}}).config.seed, 12);
  EXPECT_EQ(load_view_config(sources, {std::nullopt, {"vegetation.density=7"}}).config.vegetation.density, 7);
  std::string cli_message;
  try {
    ConfigSources bad = sources;
    bad.overrides.push_back("vegetation.density=99");
    load_config(bad);
  } catch (const InputError& e) {
    cli_message = e.what();
  }
  ASSERT_FALSE(cli_message.empty());
  try {
    load_view_config(sources, {std::nullopt, {"vegetation.density=99"}});
    FAIL() << "a bad value was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), cli_message);
  }
  for (const char* key : {"output.dir=/tmp/elsewhere", "captures.poses_file=/etc/passwd"})
    EXPECT_THROW(load_view_config(sources, {std::nullopt, {key}}), InputError) << key;
}

TEST(ViewConfig, PageEditsPassTheCostGuardOfGenerateAndWorld) {
  const fs::path dir = test::fresh_test_dir();
  for (const char* edit : {"camera.far=1000000", "vegetation.grid_spacing=0.1", "world.extent=1000000"}) {
    ViewEdits e;
    e.overrides = {edit};
    try {
      ConfigSources defaults;  // the default config, as `silva view` starts without --config
      defaults.seed = "21";
      defaults.overrides = {"output.dir=" + (dir / "out").string()};
      load_view_config(defaults, e);
      ADD_FAILURE() << edit << " was accepted";
    } catch (const InputError& err) {
      EXPECT_NE(std::string(err.what()).find("view: this config needs"), std::string::npos) << err.what();
      EXPECT_EQ(std::string(err.what()).find("--force"), std::string::npos) << "the page has no --force";
    }
  }
}

TEST(ViewWorld, EveryViewRendersAndCapturesAppendToThePoseFile) {
  const fs::path dir = test::fresh_test_dir();
  ViewWorld world(load_view_config(tiny_sources(dir / "out"), {}));
  ViewPose pose = world.start_pose();
  for (const char* name : {"rgb", "semantic", "instance", "depth", "normal"}) {
    ViewMode mode;
    ASSERT_TRUE(parse_view_mode(name, mode));
    const ViewFrame f = world.render(pose, mode, 96, 54);
    ASSERT_GT(f.jpeg.size(), 100u) << name;
    EXPECT_EQ(f.jpeg[0], 0xFF) << name;  // a JPEG's start-of-image marker
    EXPECT_EQ(f.jpeg[1], 0xD8) << name;
    EXPECT_NEAR(f.position.z() - f.ground_z, 1.5, 1e-3) << "walking: camera.ground_height over the terrain";
  }
  ViewMode unknown;
  EXPECT_FALSE(parse_view_mode("lidar", unknown));
  const nlohmann::json centre = world.probe(0.5, 0.9);  // the ground below the horizon
  EXPECT_TRUE(centre["hit"].get<bool>());
  EXPECT_GT(centre["depth_m"].get<double>(), 0);
  EXPECT_FALSE(world.probe(1.5, 0.5)["hit"].get<bool>());

  EXPECT_EQ(world.capture(pose)["frame"], 0);
  pose.yaw_deg += 90;
  EXPECT_EQ(world.capture(pose)["frame"], 1);
  const fs::path run = dir / "out" / "0000000021";
  const std::vector<PoseEntry> poses = io::read_pose_file(run / "poses.json");
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_EQ(poses[1].yaw_deg, pose.yaw_deg);
  for (const char* file : {"custom/semantic/000001.png", "custom/depth/000001.png", "custom/camera/000001.json",
                           "ontology.json", ".silva-run.json"})
    EXPECT_TRUE(fs::exists(run / file)) << file;

  // Another process's run (here: a lock this test holds) keeps the view from writing into its folder.
  {
    const io::RunLock other = io::lock_run_folder(run, /*exclusive=*/true);
    EXPECT_THROW(world.capture(pose), InputError);
  }
  EXPECT_EQ(io::read_pose_file(run / "poses.json").size(), 2u) << "the refused capture changed the pose file";
  EXPECT_EQ(world.capture(pose)["frame"], 2) << "the lock is released after each capture";
}

}  // namespace
}  // namespace silva::app

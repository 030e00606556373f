// The camera model acts on RGB only: each effect changes the rgb files and leaves every label,
// depth and normal file byte-identical; the camera files record what was applied.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "silva_process.hpp"

namespace silva::test {
namespace {

namespace fs = std::filesystem;

/// The files of a tiny run of seed 2718 with every output type and these extra --set overrides.
std::map<std::string, std::string> run_with(const fs::path& dir, const std::string& name,
                                            const std::vector<std::string>& sets) {
  const fs::path out = dir / name;
  std::vector<std::string> args = tiny_run_args(out, 2718, kAllTypes);
  for (const std::string& s : sets) args.insert(args.end(), {"--set", s});
  const ProcessResult r = run_silva(args, dir);
  EXPECT_EQ(r.code, 0) << r.err;
  return folder_files(out / "0000002718");
}

/// The files of `files` whose path starts with one of `folders` (e.g. "random/rgb/").
std::map<std::string, std::string> under(const std::map<std::string, std::string>& files,
                                         const std::vector<std::string>& folders) {
  std::map<std::string, std::string> kept;
  for (const auto& [path, bytes] : files)
    for (const std::string& f : folders)
      if (path.find(f) != std::string::npos) kept[path] = bytes;
  return kept;
}

TEST(GenerateCameraModel, EachEffectChangesOnlyTheRgb) {
  const fs::path dir = fresh_test_dir();
  const std::vector<std::string> off = {"camera.noise=false", "camera.vignetting=0", "camera.bloom=0"};
  const auto plain = run_with(dir, "plain", off);
  const std::vector<std::string> labels = {"/semantic/", "/semantic_color/", "/instance/", "/depth/", "/depth_exr/",
                                           "/normal/", "/depth_preview/"};
  ASSERT_GT(under(plain, labels).size(), 30u);
  const std::vector<std::pair<std::string, std::vector<std::string>>> effects = {
      {"noise", {"camera.noise=true", "camera.gain=8"}},
      {"vignetting", {"camera.vignetting=1"}},
      {"chromatic_aberration", {"camera.chromatic_aberration=0.003"}},
      {"bloom", {"camera.bloom=0.1"}},
      {"jpeg", {"camera.jpeg_quality=40"}},
      {"depth_of_field",
       {"camera.depth_of_field=true", "camera.f_number=0.5", "camera.sensor_width_mm=100", "camera.focus_distance=1"}},
      {"motion_blur", {"camera.motion_blur=true", "camera.shutter_s=1", "camera.autopilot_speed=5"}},
  };
  for (const auto& [name, sets] : effects) {
    SCOPED_TRACE(name);
    std::vector<std::string> all = off;
    all.insert(all.end(), sets.begin(), sets.end());
    const auto files = run_with(dir, name, all);
    EXPECT_EQ(file_differences(under(files, labels), under(plain, labels)), "");
    const auto rgb = under(files, {"autopilot/rgb/"});
    ASSERT_EQ(rgb.size(), 3u);
    for (const auto& [path, bytes] : rgb) EXPECT_NE(bytes, plain.at(path)) << path;
    // Motion blur is the autopilot's: random frames are still.
    if (name == "motion_blur") {
      EXPECT_EQ(file_differences(under(files, {"random/rgb/"}), under(plain, {"random/rgb/"})), "");
    }
    const auto camera = nlohmann::json::parse(files.at("autopilot/camera/000000.json"))["camera_model"];
    EXPECT_EQ(camera["noise"].is_null(), name != "noise");
    EXPECT_EQ(camera["depth_of_field"].is_null(), name != "depth_of_field");
    EXPECT_EQ(camera["motion_blur"].is_null(), name != "motion_blur");
    EXPECT_EQ(camera["vignetting"], name == "vignetting" ? 1.0 : 0.0);
    EXPECT_EQ(camera["chromatic_aberration"], name == "chromatic_aberration" ? 0.003 : 0.0);
    EXPECT_EQ(camera["bloom"], name == "bloom" ? 0.1 : 0.0);
    EXPECT_EQ(camera["chroma"], 1.0);  // a day frame is exposed at the base gain
    EXPECT_EQ(camera["jpeg_quality"], name == "jpeg" ? 40 : 0);
    const auto random_camera = nlohmann::json::parse(files.at("random/camera/000000.json"))["camera_model"];
    EXPECT_TRUE(random_camera["motion_blur"].is_null());
  }
}

}  // namespace
}  // namespace silva::test

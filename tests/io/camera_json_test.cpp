#include "io/camera_json.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/error.hpp"

namespace silva::io {
namespace {

CameraRecord sample(bool with_trail) {
  CameraRecord r;
  r.frame = 17;
  r.sequence = with_trail ? "autopilot" : "random";
  r.perspective = with_trail ? Perspective::Ground : Perspective::Aerial;
  r.camera = Camera::from_fov(1920, 1080, 90.0, 0.05, 150.0);
  r.yaw_deg = 33.3;
  r.pitch_deg = -12.25;
  r.roll_deg = 0.1;
  r.camera.camera_to_world = pose_from_angles(Vec3d(10.1, -3.7, 1.5), r.yaw_deg, r.pitch_deg, r.roll_deg);
  if (with_trail) r.trail_s = 123.456789012345;
  return r;
}

void expect_same(const CameraRecord& a, const CameraRecord& b) {
  EXPECT_EQ(a.frame, b.frame);
  EXPECT_EQ(a.sequence, b.sequence);
  EXPECT_EQ(a.perspective, b.perspective);
  EXPECT_EQ(a.camera.width, b.camera.width);
  EXPECT_EQ(a.camera.height, b.camera.height);
  EXPECT_EQ(a.camera.fx, b.camera.fx);
  EXPECT_EQ(a.camera.fy, b.camera.fy);
  EXPECT_EQ(a.camera.cx, b.camera.cx);
  EXPECT_EQ(a.camera.cy, b.camera.cy);
  EXPECT_EQ(a.camera.camera_to_world, b.camera.camera_to_world);  // bit-exact doubles
  EXPECT_EQ(a.camera.near, b.camera.near);
  EXPECT_EQ(a.camera.far, b.camera.far);
  EXPECT_EQ(a.yaw_deg, b.yaw_deg);
  EXPECT_EQ(a.pitch_deg, b.pitch_deg);
  EXPECT_EQ(a.roll_deg, b.roll_deg);
  EXPECT_EQ(a.trail_s, b.trail_s);
}

TEST(CameraJson, RoundTripsExactly) {
  for (bool trail : {true, false}) {
    const CameraRecord r = sample(trail);
    const std::string text = camera_json(r);
    expect_same(r, parse_camera_json(text, "cam.json"));
    EXPECT_EQ(camera_json(parse_camera_json(text, "cam.json")), text);
  }
}

TEST(CameraJson, HasContractKeysInOrder) {
  const auto j = nlohmann::ordered_json::parse(camera_json(sample(false)));
  std::vector<std::string> keys;
  for (const auto& [k, v] : j.items()) keys.push_back(k);
  EXPECT_EQ(keys, (std::vector<std::string>{"frame", "sequence", "perspective", "width", "height", "K",
                                            "camera_to_world", "near", "far", "yaw_deg", "pitch_deg", "roll_deg",
                                            "trail_s"}));
  EXPECT_TRUE(j["trail_s"].is_null());
  EXPECT_EQ(j["perspective"], "aerial");
  EXPECT_DOUBLE_EQ(j["K"][0][0].get<double>(), 960.0);
  EXPECT_EQ(j["K"][1][2], 540.0);
  EXPECT_EQ(j["K"][2][2], 1.0);
  EXPECT_EQ(j["camera_to_world"][3][3], 1.0);
  EXPECT_EQ(j["camera_to_world"][0][3], 10.1);  // row-major: translation in the last column
}

TEST(CameraJson, MalformedFileIsInputErrorNamingFileAndKey) {
  auto j = nlohmann::json::parse(camera_json(sample(true)));
  j.erase("near");
  try {
    parse_camera_json(j.dump(), "cams/000001.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cams/000001.json"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("near"), std::string::npos);
  }
  j = nlohmann::json::parse(camera_json(sample(true)));
  j["perspective"] = "sideways";
  EXPECT_THROW(parse_camera_json(j.dump(), "x.json"), InputError);
  j = nlohmann::json::parse(camera_json(sample(true)));
  j["camera_to_world"][1] = {1, 2, 3};
  EXPECT_THROW(parse_camera_json(j.dump(), "x.json"), InputError);
  EXPECT_THROW(parse_camera_json("{not json", "x.json"), InputError);
  EXPECT_THROW(read_camera_json("/nonexistent/silva/camera.json"), InputError);
}

}  // namespace
}  // namespace silva::io

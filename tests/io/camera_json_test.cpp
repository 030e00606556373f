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
  r.model.noise = SensorNoise{10000, 3, 2.5};
  r.model.vignetting = 0.25;
  if (with_trail) {  // every optic on, with values that need all 17 digits
    r.model.chromatic_aberration = 0.0031;
    r.model.bloom = 0.0123;
    r.model.depth_of_field = DepthOfField{2.8, 3.3, 5.65 / 3.0};
    r.model.motion = ExposureMotion{1.0 / 60.0, pose_from_angles(Vec3d(10.09, -3.7, 1.5), 33.2, -12.25, 0.1),
                                    pose_from_angles(Vec3d(10.11, -3.7, 1.5), 33.4, -12.25, 0.1)};
  }
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
  EXPECT_EQ(a.model, b.model);  // bit-exact doubles
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
                                            "trail_s", "camera_model"}));
  EXPECT_TRUE(j["trail_s"].is_null());
  EXPECT_EQ(j["perspective"], "aerial");
  EXPECT_DOUBLE_EQ(j["K"][0][0].get<double>(), 960.0);
  EXPECT_EQ(j["K"][1][2], 540.0);
  EXPECT_EQ(j["K"][2][2], 1.0);
  EXPECT_EQ(j["camera_to_world"][3][3], 1.0);
  EXPECT_EQ(j["camera_to_world"][0][3], 10.1);  // row-major: translation in the last column
  const auto& model = j["camera_model"];
  std::vector<std::string> model_keys;
  for (const auto& [k, v] : model.items()) model_keys.push_back(k);
  EXPECT_EQ(model_keys,
            (std::vector<std::string>{"noise", "vignetting", "chromatic_aberration", "bloom", "chroma",
                                      "jpeg_quality", "depth_of_field", "motion_blur"}));
  EXPECT_EQ(model["noise"]["full_well_e"], 10000.0);
  EXPECT_EQ(model["noise"]["read_noise_e"], 3.0);
  EXPECT_EQ(model["noise"]["gain"], 2.5);
  EXPECT_EQ(model["vignetting"], 0.25);
  EXPECT_TRUE(model["depth_of_field"].is_null());  // off
  EXPECT_TRUE(model["motion_blur"].is_null());
  const auto on = nlohmann::ordered_json::parse(camera_json(sample(true)))["camera_model"];
  EXPECT_EQ(on["depth_of_field"]["f_number"], 2.8);
  EXPECT_EQ(on["motion_blur"]["shutter_s"], 1.0 / 60.0);
  EXPECT_EQ(on["motion_blur"]["close_camera_to_world"][0][3], 10.11);
}

TEST(CameraJson, MalformedCameraModelIsInputErrorNamingTheKey) {
  auto j = nlohmann::json::parse(camera_json(sample(true)));
  j["camera_model"]["depth_of_field"].erase("f_number");
  try {
    parse_camera_json(j.dump(), "cams/000002.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("f_number"), std::string::npos) << e.what();
  }
  j = nlohmann::json::parse(camera_json(sample(true)));
  j["camera_model"]["noise"] = 3;
  EXPECT_THROW(parse_camera_json(j.dump(), "x.json"), InputError);
  j = nlohmann::json::parse(camera_json(sample(true)));
  j.erase("camera_model");
  EXPECT_THROW(parse_camera_json(j.dump(), "x.json"), InputError);
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

/// The message parse_camera_json gives for `j` (empty when it parses).
std::string refusal(const nlohmann::json& j) {
  try {
    parse_camera_json(j.dump(), "c.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CameraJson, RefusesCamerasNoReaderCanProjectWith) {
  const auto base = nlohmann::json::parse(camera_json(sample(true)));
  EXPECT_EQ(refusal(base), "");
  const auto with = [&](auto edit) {
    nlohmann::json j = base;
    edit(j);
    return refusal(j);
  };
  // Values a damaged dataset held that crashed or hung verify and card, or wrote nan into exports.
  EXPECT_NE(with([](auto& j) { j["K"][0][0] = 0.0; }).find("'K'"), std::string::npos);
  EXPECT_NE(with([](auto& j) { j["K"][1][1] = 1e-300; }).find("'K'"), std::string::npos);
  EXPECT_NE(with([](auto& j) { j["K"][0][2] = 1e308; }).find("'K'"), std::string::npos);
  EXPECT_NE(with([](auto& j) { j["K"][0][1] = 0.5; }).find("'K'"), std::string::npos);
  EXPECT_NE(with([](auto& j) { j["camera_to_world"][0][3] = 1e19; }).find("'camera_to_world'"), std::string::npos);
  EXPECT_NE(with([](auto& j) { j["camera_to_world"][0][3] = -1e300; }).find("outside the world"), std::string::npos);
  EXPECT_NE(with([](auto& j) { j["camera_to_world"][0][0] = 2.0; }).find("rotation"), std::string::npos);
  EXPECT_NE(with([](auto& j) { j["camera_to_world"][3][0] = 1.0; }).find("last row"), std::string::npos);
  EXPECT_NE(with([](auto& j) {  // a mirror: orthonormal, determinant -1
              for (int r = 0; r < 3; ++r) j["camera_to_world"][r][0] = -j["camera_to_world"][r][0].template get<double>();
            }).find("rotation"), std::string::npos);
  EXPECT_NE(with([](auto& j) { j["near"] = 0.0; }).find("'near'"), std::string::npos);
  EXPECT_NE(with([](auto& j) { j["far"] = 0.01; }).find("'near'"), std::string::npos);
  EXPECT_NE(with([](auto& j) { j["width"] = 16384; }).find("width"), std::string::npos);
}

}  // namespace
}  // namespace silva::io

namespace silva::io {
namespace {

TEST(CameraJson, StereoRecordRoundTripsAndIsCheckedWhenPresent) {
  CameraRecord r = sample(false);
  EXPECT_EQ(camera_json(r).find("\"stereo\""), std::string::npos);  // one camera: no stereo key
  r.stereo = StereoRecord{true, 0.12};
  const std::string text = camera_json(r);
  EXPECT_NE(text.find("\"camera\": \"right\""), std::string::npos);
  const CameraRecord back = parse_camera_json(text, "cam.json");
  ASSERT_TRUE(back.stereo.has_value());
  EXPECT_EQ(*back.stereo, *r.stereo);
  nlohmann::json j = nlohmann::json::parse(text);
  j["stereo"]["camera"] = "middle";
  EXPECT_THROW(parse_camera_json(j.dump(), "cams/000001.json"), InputError);
  j["stereo"]["camera"] = "left";
  j["stereo"]["baseline_m"] = -0.12;
  try {
    parse_camera_json(j.dump(), "cams/000001.json");
    FAIL() << "a negative baseline was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("baseline_m"), std::string::npos) << e.what();
  }
}

TEST(CameraJson, LightingRecordRoundTripsAndIsAbsentWhenUnset) {
  CameraRecord r = sample(false);
  EXPECT_EQ(camera_json(r).find("\"lighting\""), std::string::npos);  // files without it keep their bytes
  LightingRecord l;
  l.time_of_day = "dusk";
  l.weather = "mist";
  l.randomized = true;
  l.sun_elevation_deg = 23.25;
  l.sun_azimuth_deg = 301.5;
  l.cloud_cover = 0.4;
  l.fog_density_scale = 1.75;
  l.white_balance_k = 5900;
  l.exposure = "auto";
  l.exposure_compensation_ev = -0.25;
  l.ev100 = 11.5;
  r.lighting = l;
  const std::string text = camera_json(r);
  const CameraRecord back = parse_camera_json(text, "cam.json");
  ASSERT_TRUE(back.lighting.has_value());
  EXPECT_EQ(*back.lighting, l);
  EXPECT_EQ(camera_json(back), text);
  l.ev100.reset();  // no rgb: no exposure
  r.lighting = l;
  EXPECT_EQ(parse_camera_json(camera_json(r), "cam.json").lighting, l);
  nlohmann::json j = nlohmann::json::parse(camera_json(r));
  j["lighting"]["exposure"] = "manual";
  try {
    parse_camera_json(j.dump(), "cams/000004.json");
    FAIL() << "a bad exposure mode was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cams/000004.json: lighting: 'exposure'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace silva::io

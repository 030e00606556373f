#include "io/pose_file.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/camera.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io_test_util.hpp"

namespace silva::io {
namespace {

/// The message of the InputError `f` throws, or "" if none.
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string matrix_pose_json(const Mat4d& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < 4; ++r) rows.push_back({m(r, 0), m(r, 1), m(r, 2), m(r, 3)});
  return nlohmann::json{{"poses", {{{"camera_to_world", rows}}}}}.dump();
}

TEST(PoseFile, JsonAnglesAndMatrixRoundTrip) {
  const Mat4d m = pose_from_angles(Vec3d(4, 5, 6), -30, 12.5, 3);
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < 4; ++r) rows.push_back({m(r, 0), m(r, 1), m(r, 2), m(r, 3)});
  const nlohmann::json j = {{"poses",
                             {{{"position", {1.5, -2, 3}}, {"yaw_deg", 90}, {"pitch_deg", -10}, {"roll_deg", 2}},
                              {{"position", {7, 8}}, {"yaw_deg", 0}, {"pitch_deg", 0}, {"roll_deg", 0}},
                              {{"camera_to_world", rows}}}}};
  const auto poses = parse_pose_json(j.dump(), "p.json");
  ASSERT_EQ(poses.size(), 3u);
  EXPECT_EQ(poses[0].position, Vec3d(1.5, -2, 3));
  EXPECT_TRUE(poses[0].has_z);
  EXPECT_EQ(poses[0].yaw_deg, 90);
  EXPECT_EQ(poses[0].pitch_deg, -10);
  EXPECT_EQ(poses[0].roll_deg, 2);
  EXPECT_TRUE(poses[0].rotation.isApprox(rotation_from_angles(90, -10, 2)));
  EXPECT_FALSE(poses[1].has_z);
  EXPECT_EQ(poses[1].position.head<2>(), Eigen::Vector2d(7, 8));
  EXPECT_EQ(poses[2].position, Vec3d(4, 5, 6));
  EXPECT_EQ(poses[2].rotation, Mat3d(m.block<3, 3>(0, 0)));  // the file's matrix is kept as given
  EXPECT_NEAR(poses[2].yaw_deg, -30, 1e-9);
  EXPECT_NEAR(poses[2].pitch_deg, 12.5, 1e-9);
  EXPECT_NEAR(poses[2].roll_deg, 3, 1e-9);
}

TEST(PoseFile, CsvRoundTripAndOptionalZ) {
  const std::string text = "x,y,z,yaw_deg,pitch_deg,roll_deg\r\n1,2,3,45,-5,0.5\r\n\n-1e2, 0.25 ,,+10,0,0\n";
  const auto poses = parse_pose_csv(text, "p.csv");
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_EQ(poses[0].position, Vec3d(1, 2, 3));
  EXPECT_EQ(poses[0].yaw_deg, 45);
  EXPECT_EQ(poses[0].pitch_deg, -5);
  EXPECT_EQ(poses[0].roll_deg, 0.5);
  EXPECT_TRUE(poses[0].has_z);
  EXPECT_EQ(poses[1].position.x(), -100);
  EXPECT_EQ(poses[1].position.y(), 0.25);
  EXPECT_FALSE(poses[1].has_z);
  EXPECT_EQ(poses[1].yaw_deg, 10);
}

TEST(PoseFile, ShippedExamplesParseAndAgree) {
  const std::string dir = std::string(SILVA_SOURCE_DIR) + "/configs/";
  const auto js = read_pose_file(dir + "poses.example.json");
  const auto cs = read_pose_file(dir + "poses.example.csv");
  ASSERT_GE(js.size(), 3u);
  ASSERT_EQ(cs.size(), 3u);
  for (size_t k = 0; k < cs.size(); ++k) {
    EXPECT_EQ(js[k].position, cs[k].position);
    EXPECT_EQ(js[k].has_z, cs[k].has_z);
    EXPECT_EQ(js[k].yaw_deg, cs[k].yaw_deg);
  }
}

TEST(PoseFile, NonOrthonormalMatrixIsRejected) {
  Mat4d m = pose_from_angles(Vec3d(0, 0, 1), 10, 0, 0);
  m(0, 0) *= 1.001;
  const std::string e = error_of([&] { parse_pose_json(matrix_pose_json(m), "bad.json"); });
  EXPECT_NE(e.find("bad.json"), std::string::npos) << e;
  EXPECT_NE(e.find("pose 0"), std::string::npos) << e;
  EXPECT_NE(e.find("orthonormal"), std::string::npos) << e;
  Mat4d tiny = pose_from_angles(Vec3d(0, 0, 1), 10, 0, 0);
  tiny(0, 0) += 1e-7;  // within tolerance
  EXPECT_EQ(error_of([&] { parse_pose_json(matrix_pose_json(tiny), "ok.json"); }), "");
  Mat4d mirror = Mat4d::Identity();
  mirror(0, 0) = -1;
  EXPECT_NE(error_of([&] { parse_pose_json(matrix_pose_json(mirror), "m.json"); }).find("reflection"), std::string::npos);
}

TEST(PoseFile, JsonErrorsNameFileAndPoseIndex) {
  const std::string ok = R"({"position": [0, 0, 1], "yaw_deg": 0, "pitch_deg": 0, "roll_deg": 0})";
  auto err = [&](const std::string& second) {
    return error_of([&] { parse_pose_json(R"({"poses": [)" + ok + "," + second + "]}", "trip.json"); });
  };
  const std::string missing = err(R"({"position": [0, 0, 1], "yaw_deg": 0, "roll_deg": 0})");
  EXPECT_NE(missing.find("trip.json: pose 1"), std::string::npos) << missing;
  EXPECT_NE(missing.find("pitch_deg"), std::string::npos) << missing;
  const std::string wrong_type = err(R"({"position": [0, 0, 1], "yaw_deg": "north", "pitch_deg": 0, "roll_deg": 0})");
  EXPECT_NE(wrong_type.find("trip.json: pose 1"), std::string::npos) << wrong_type;
  EXPECT_NE(wrong_type.find("must be a number"), std::string::npos) << wrong_type;
  EXPECT_NE(err(R"({"position": [0, "a", 1], "yaw_deg": 0, "pitch_deg": 0, "roll_deg": 0})").find("pose 1"), std::string::npos);
  EXPECT_NE(err(R"({"position": [0], "yaw_deg": 0, "pitch_deg": 0, "roll_deg": 0})").find("pose 1"), std::string::npos);
  EXPECT_NE(err(R"({"yaw_deg": 0})").find("pose 1"), std::string::npos);
  EXPECT_NE(err(R"({"camera_to_world": [[1,0,0,0],[0,1,0,0],[0,0,1,0]]})").find("4x4"), std::string::npos);
  EXPECT_NE(err("7").find("pose 1"), std::string::npos);
  const std::string unknown = err(R"({"position": [0, 0, 1], "yaw_deg": 0, "pitch_deg": 0, "roll_deg": 0, "fov": 60})");
  EXPECT_NE(unknown.find("pose 1: unknown key \"fov\""), std::string::npos) << unknown;
  EXPECT_NE(err(R"({"camera_to_world": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]], "yaw_deg": 3})").find("\"yaw_deg\""),
            std::string::npos);
  EXPECT_NE(error_of([] { parse_pose_json(R"({"poses": []})", "e.json"); }).find("no poses"), std::string::npos);
  EXPECT_NE(error_of([] { parse_pose_json(R"({"pose": []})", "e.json"); }).find("poses"), std::string::npos);
  EXPECT_NE(error_of([] { parse_pose_json("{", "e.json"); }).find("e.json"), std::string::npos);
}

TEST(PoseFile, CsvErrorsNameFileLineAndPose) {
  auto err = [](const std::string& text) { return error_of([&] { parse_pose_csv(text, "walk.csv"); }); };
  const std::string header = err("x,y,yaw_deg\n1,2,3\n");
  EXPECT_NE(header.find("walk.csv: line 1"), std::string::npos) << header;
  EXPECT_NE(header.find("x,y,z,yaw_deg,pitch_deg,roll_deg"), std::string::npos) << header;
  const std::string nonnum = err("x,y,z,yaw_deg,pitch_deg,roll_deg\n1,2,3,4,5,6\n1,2,3,abc,5,6\n");
  EXPECT_NE(nonnum.find("walk.csv: line 3 (pose 1)"), std::string::npos) << nonnum;
  EXPECT_NE(nonnum.find("yaw_deg"), std::string::npos) << nonnum;
  EXPECT_NE(err("x,y,z,yaw_deg,pitch_deg,roll_deg\n1,2,3,4,5\n").find("line 2 (pose 0)"), std::string::npos);
  EXPECT_NE(err("x,y,z,yaw_deg,pitch_deg,roll_deg\n1,2,3,4,5,6,7\n").find("line 2"), std::string::npos);
  EXPECT_NE(err("x,y,z,yaw_deg,pitch_deg,roll_deg\n1,2,3,4,5,\n").find("roll_deg"), std::string::npos);
  EXPECT_NE(err("x,y,z,yaw_deg,pitch_deg,roll_deg\n1,2,3,4,5,nan\n").find("roll_deg"), std::string::npos);
  EXPECT_NE(err("x,y,z,yaw_deg,pitch_deg,roll_deg\n1,2,3,4,5,6x\n").find("roll_deg"), std::string::npos);
  EXPECT_NE(err("x,y,z,yaw_deg,pitch_deg,roll_deg\n").find("no poses"), std::string::npos);
  EXPECT_NE(err("").find("walk.csv"), std::string::npos);
  // A spreadsheet's "Unicode text": UTF-16 with its byte-order mark; the message says so instead of quoting bytes.
  std::string utf16 = "\xFF\xFE";
  for (const char c : std::string("x,y,z,yaw_deg,pitch_deg,roll_deg\n")) utf16 += std::string{c, '\0'};
  EXPECT_NE(err(utf16).find("not UTF-8 text"), std::string::npos) << err(utf16);
}

TEST(PoseFile, ReadPicksFormatByExtension) {
  const auto dir = test::scratch_dir("pose_file_ext");
  write_file_atomic(dir / "p.CSV", std::string_view("x,y,z,yaw_deg,pitch_deg,roll_deg\n1,2,3,4,5,6\n"));
  EXPECT_EQ(read_pose_file(dir / "p.CSV").size(), 1u);
  write_file_atomic(dir / "p.json", std::string_view("x,y,z,yaw_deg,pitch_deg,roll_deg\n"));
  EXPECT_THROW(read_pose_file(dir / "p.json"), InputError);
  EXPECT_THROW(read_pose_file(dir / "absent.json"), InputError);
}

}  // namespace
}  // namespace silva::io

// run.json's pixel_shares count every written pixel by class, as the semantic images show them.
#include <gtest/gtest.h>

#include <array>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/ontology.hpp"
#include "silva_process.hpp"

namespace silva::test {
namespace {

namespace fs = std::filesystem;

TEST(GeneratePixelShares, RunRecordSharesAreTheSemanticImagesClassCounts) {
  const fs::path dir = fresh_test_dir();
  const fs::path out = dir / "out";
  const ProcessResult r = run_silva(tiny_run_args(out, 4242, R"(["rgb","semantic"])"), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const fs::path run = out / "0000004242";
  std::array<uint64_t, kRoleCount> counted{};
  uint64_t pixels = 0;
  for (const auto& entry : fs::recursive_directory_iterator(run)) {
    if (entry.path().parent_path().filename() != "semantic") continue;
    const cv::Mat ids = cv::imread(entry.path().string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(ids.type(), CV_8UC1) << entry.path();
    for (int v = 0; v < ids.rows; ++v)
      for (int u = 0; u < ids.cols; ++u) ++counted[ids.at<uint8_t>(v, u)];  // default ontology: id = role
    pixels += uint64_t(ids.total());
  }
  ASSERT_EQ(pixels, 5u * 64u * 48u);  // 3 autopilot + 2 random frames
  const auto shares = nlohmann::json::parse(read_file(run / "run.json")).at("pixel_shares");
  EXPECT_EQ(shares.at("pixels").get<uint64_t>(), pixels);
  for (int c = 0; c < kRoleCount; ++c)
    EXPECT_DOUBLE_EQ(shares.at("by_class").at(role_name(Role(c))).get<double>(), double(counted[size_t(c)]) / double(pixels))
        << role_name(Role(c));
  const double soil = shares.at("bare_soil_look").get<double>();
  EXPECT_GE(soil, 0.0);
  EXPECT_LE(soil, double(counted[size_t(Role::Ground)]) / double(pixels));  // only forest-floor pixels count
}

}  // namespace
}  // namespace silva::test

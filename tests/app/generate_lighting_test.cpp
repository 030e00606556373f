// Lighting and weather through `silva generate` and `silva validate`: the time-of-day presets keep
// their brightness order on real views (dusk over night on average), weather changes RGB only, and every weather preset
// survives `validate --print`.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <map>

#include <opencv2/imgcodecs.hpp>

#include "silva_process.hpp"

namespace silva::test {
namespace {

namespace fs = std::filesystem;

/// Mean Rec.709 luma of an 8-bit sRGB image file.
double mean_luma(const fs::path& png) {
  const cv::Mat bgr = cv::imread(png.string(), cv::IMREAD_COLOR);
  EXPECT_FALSE(bgr.empty()) << png;
  double sum = 0;
  for (int y = 0; y < bgr.rows; ++y)
    for (int x = 0; x < bgr.cols; ++x) {
      const cv::Vec3b p = bgr.at<cv::Vec3b>(y, x);
      sum += 0.2126 * p[2] + 0.7152 * p[1] + 0.0722 * p[0];
    }
  return sum / double(bgr.rows * bgr.cols);
}

/// Renders `views` random views of `seed` at 160x90 (RGB only) under time of day `time` and `weather`.
fs::path render_random_views(const fs::path& dir, int64_t seed, const std::string& time, int views, bool aerial,
                             const std::string& weather = "clear") {
  const fs::path out = dir / (time + "-" + weather + (aerial ? "-aerial" : "-ground"));
  const ProcessResult r = run_silva(
      {"generate", "--seed", std::to_string(seed), "--out", out.string(), "--set", "output.resolution=160x90",
       "--set", R"(captures.sequences=["random"])", "--set", "captures.random_count=" + std::to_string(views), "--set",
       "world.extent=256", "--set", "world.render_distance=160", "--set", std::string("captures.aerial=") +
       (aerial ? "true" : "false"), "--set", "lighting.time_of_day=" + time, "--set", "lighting.weather=" + weather, "--set",
       R"(output.types=["rgb"])"},
      dir);
  EXPECT_EQ(r.code, 0) << r.err;
  char name[16];
  std::snprintf(name, sizeof name, "%010lld", static_cast<long long>(seed));
  return out / name / "random" / "rgb";
}

// Day beats dusk on every view. Dusk beats night on the mean of each set of views but not always view by
// view: at the presets' fixed exposures, a view under a closed canopy at dusk (the sun below the crowns, only
// the sky light they leave) can come out darker than the same view by moonlight, which reaches through gaps.
TEST(GenerateLighting, DayIsBrighterThanDuskIsBrighterThanNightAndNightMistOnEveryView) {
  const fs::path dir = fresh_test_dir();
  constexpr int kViews = 20;
  for (const int64_t seed : {int64_t{1414213562}, int64_t{42}, int64_t{271828}}) {
    for (const bool aerial : {false, true}) {
      if (aerial && seed != 42) continue;  // one seed from the air as well
      const fs::path day = render_random_views(dir, seed, "day", kViews, aerial);
      const fs::path dusk = render_random_views(dir, seed, "dusk", kViews, aerial);
      const fs::path night = render_random_views(dir, seed, "night", kViews, aerial);
      const fs::path night_mist = aerial ? fs::path() : render_random_views(dir, seed, "night", kViews, aerial, "mist");
      double dusk_sum = 0, night_sum = 0;
      for (int i = 0; i < kViews; ++i) {
        char file[16];
        std::snprintf(file, sizeof file, "%06d.png", i);
        const double d = mean_luma(day / file), k = mean_luma(dusk / file), n = mean_luma(night / file);
        SCOPED_TRACE(testing::Message() << "seed " << seed << (aerial ? " aerial" : " ground") << " view " << i);
        EXPECT_GT(d, k);
        EXPECT_GT(n, 1.0);  // night is dark, not black
        dusk_sum += k;
        night_sum += n;
        // Inside the mist (ground views) the fog shades the moonlight it scatters: no brighter than a clear night.
        // From 15 m up the camera looks down onto the mist's moonlit top, which is brighter, as a fog sea is.
        if (!aerial) {
          EXPECT_LE(mean_luma(night_mist / file), n);
        }
      }
      EXPECT_GT(dusk_sum, 1.5 * night_sum) << "seed " << seed << (aerial ? " aerial" : " ground");
    }
  }
}

/// Share of a view's ground-labelled pixels (semantic id 1) that look like fallen leaves: red above 1.3 x green.
double leaf_litter_share(const fs::path& rgb_png, const fs::path& semantic_png) {
  const cv::Mat bgr = cv::imread(rgb_png.string(), cv::IMREAD_COLOR);
  const cv::Mat sem = cv::imread(semantic_png.string(), cv::IMREAD_UNCHANGED);
  EXPECT_FALSE(bgr.empty() || sem.empty()) << rgb_png;
  int ground = 0, litter = 0;
  for (int y = 0; y < bgr.rows; ++y)
    for (int x = 0; x < bgr.cols; ++x) {
      if (sem.at<uint8_t>(y, x) != 1) continue;
      const cv::Vec3b p = bgr.at<cv::Vec3b>(y, x);
      ++ground;
      litter += p[2] > 1.3 * p[1] ? 1 : 0;
    }
  return ground ? double(litter) / ground : 0.0;
}

TEST(GenerateLighting, AutumnLaysMoreLeafLitterOnTheFloorWithTheSameLabels) {
  const fs::path dir = fresh_test_dir();
  const auto render = [&](const std::string& season) {
    std::vector<std::string> args = tiny_run_args(dir / season, 1414213562, R"(["rgb","semantic"])");
    args.insert(args.end(), {"--set", R"(captures.sequences=["random"])", "--set", "captures.random_count=4", "--set",
                             "output.resolution=160x90", "--set", "camera.noise=false", "--set",
                             "vegetation.season=" + season});
    const ProcessResult r = run_silva(args, dir);
    EXPECT_EQ(r.code, 0) << r.err;
    return dir / season / "1414213562" / "random";
  };
  const fs::path summer = render("summer"), autumn = render("autumn");
  EXPECT_EQ(file_differences(folder_files(summer / "semantic"), folder_files(autumn / "semantic")), "");
  double summer_total = 0, autumn_total = 0;
  for (int i = 0; i < 4; ++i) {
    char file[16];
    std::snprintf(file, sizeof file, "%06d.png", i);
    const double s = leaf_litter_share(summer / "rgb" / file, summer / "semantic" / file);
    const double a = leaf_litter_share(autumn / "rgb" / file, autumn / "semantic" / file);
    SCOPED_TRACE(testing::Message() << "view " << i << ": summer " << s << ", autumn " << a);
    EXPECT_GE(a, s);
    summer_total += s / 4;
    autumn_total += a / 4;
  }
  EXPECT_GT(autumn_total, summer_total + 0.05);
}

TEST(GenerateLighting, WeatherLeavesLabelsAndDepthByteIdentical) {
  const fs::path dir = fresh_test_dir();
  const auto labels = [&](const std::string& weather) {
    std::vector<std::string> args =
        tiny_run_args(dir / weather, 23, R"(["rgb","semantic","semantic_color","instance","depth","depth_exr","normal"])");
    args.insert(args.end(), {"--set", "lighting.weather=" + weather, "--set", "vegetation.season=winter"});  // snow's
    const ProcessResult r = run_silva(args, dir);
    EXPECT_EQ(r.code, 0) << r.err;
    std::map<std::string, std::string> files = folder_files(dir / weather);
    std::map<std::string, std::string> kept;  // the manifest and the card name the weather
    for (auto& [name, bytes] : files)
      if (name.find("/rgb/") == std::string::npos && !name.ends_with("manifest.json") &&
          !name.ends_with(".silva-run.json") && !name.ends_with("CARD.md") && !name.ends_with("card.json"))
        kept[name] = std::move(bytes);
    return std::pair{kept, files};
  };
  const auto [clear, clear_all] = labels("clear");
  ASSERT_GT(clear.size(), 20u);
  for (const char* weather : {"overcast", "mist", "rain", "snow"}) {
    const auto [other, other_all] = labels(weather);
    EXPECT_EQ(file_differences(clear, other), "") << weather;
    // ... while the RGB does change.
    bool rgb_differs = false;
    for (const auto& [name, bytes] : other_all)
      if (name.find("/rgb/") != std::string::npos && clear_all.at(name) != bytes) rgb_differs = true;
    EXPECT_TRUE(rgb_differs) << weather;
  }
}

TEST(GenerateLighting, EveryWeatherPresetRoundTripsThroughValidatePrint) {
  const fs::path dir = fresh_test_dir();
  for (const char* weather : {"clear", "overcast", "mist", "rain", "snow"}) {
    const ProcessResult first = run_silva({"validate", "--set", "seed=7", "--set", std::string("lighting.weather=") + weather,
                                           "--set", "vegetation.season=winter", "--print"},
                                          dir);
    ASSERT_EQ(first.code, 0) << first.err;
    EXPECT_NE(first.out.find(std::string("weather = \"") + weather + "\""), std::string::npos) << first.out;
    const fs::path printed = dir / (std::string(weather) + ".toml");
    std::ofstream(printed) << first.out;
    const ProcessResult second = run_silva({"validate", "--config", printed.string(), "--print"}, dir);
    ASSERT_EQ(second.code, 0) << second.err;
    EXPECT_EQ(second.out, first.out) << weather;
  }
  // A weather the config defines itself travels with it.
  const fs::path own = dir / "own.toml";
  std::ofstream(own) << "seed = 7\n[lighting]\nweather = \"drizzle\"\n[lighting.weather_presets.drizzle]\n"
                        "wetness = 0.4\nrain_streaks = 0.1\n";
  const ProcessResult first = run_silva({"validate", "--config", own.string(), "--print"}, dir);
  ASSERT_EQ(first.code, 0) << first.err;
  EXPECT_NE(first.out.find("[lighting.weather_presets.drizzle]"), std::string::npos) << first.out;
  const fs::path printed = dir / "own-printed.toml";
  std::ofstream(printed) << first.out;
  const ProcessResult second = run_silva({"validate", "--config", printed.string(), "--print"}, dir);
  ASSERT_EQ(second.code, 0) << second.err;
  EXPECT_EQ(second.out, first.out);
}

}  // namespace
}  // namespace silva::test

// Same seed and config with --threads 1, 2 and 6 write byte-identical files (run.json aside); 6 threads draw the
// sun's passes beside the cameras' and keep four frames in flight.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "silva_process.hpp"

namespace silva::test {
namespace {

namespace fs = std::filesystem;

TEST(GenerateThreads, OneTwoAndSixThreadsWriteIdenticalFiles) {
  const fs::path dir = fresh_test_dir();
  const int counts[3] = {1, 2, 6};
  std::map<std::string, std::string> files[3];
  for (int k = 0; k < 3; ++k) {
    const int threads = counts[k];
    const fs::path out = dir / std::string("t").append(std::to_string(threads));
    std::vector<std::string> args = tiny_run_args(out, 31337, kAllTypes);
    args.insert(args.end(), {"--threads", std::to_string(threads)});
    const ProcessResult r = run_silva(args, dir);
    ASSERT_EQ(r.code, 0) << r.err;
    files[k] = folder_files(out / "0000031337");
    // The thread count is recorded in run.json, nowhere else.
    const auto record = nlohmann::json::parse(read_file(out / "0000031337" / "run.json"));
    EXPECT_EQ(record.at("threads"), threads);
    // Each ECS system's wall time: the Render phase's within the capture's wall time.
    const auto& systems = record.at("systems_s");
    for (const char* name : {"aim_camera", "stream_chunks", "prepare_scene", "render_views", "write_dataset"})
      EXPECT_TRUE(systems.at(name).is_number()) << name;
    EXPECT_GT(systems.at("render_views").get<double>(), 0.0);
    EXPECT_LE(systems.at("render_views").get<double>(), record.at("timings_s").at("wall").get<double>());
  }
  EXPECT_GT(files[0].size(), 40u);
  // The dataset card is compared too: it quotes no timings.
  for (const char* card : {"CARD.md", "card.json", "card_classes.png", "card_poses.png"}) EXPECT_EQ(files[0].count(card), 1u) << card;
  EXPECT_EQ(file_differences(files[0], files[1]), "");
  EXPECT_EQ(file_differences(files[0], files[2]), "");
}

}  // namespace
}  // namespace silva::test

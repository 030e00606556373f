// Same seed and config with --threads 1 and --threads 2 write byte-identical files (run.json aside).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "silva_process.hpp"

namespace silva::test {
namespace {

namespace fs = std::filesystem;

TEST(GenerateThreads, OneAndTwoThreadsWriteIdenticalFiles) {
  const fs::path dir = fresh_test_dir();
  std::map<std::string, std::string> files[2];
  for (int threads : {1, 2}) {
    const fs::path out = dir / std::string("t").append(std::to_string(threads));
    std::vector<std::string> args = tiny_run_args(out, 31337, kAllTypes);
    args.insert(args.end(), {"--threads", std::to_string(threads)});
    const ProcessResult r = run_silva(args, dir);
    ASSERT_EQ(r.code, 0) << r.err;
    files[threads - 1] = folder_files(out / "0000031337");
    // The thread count is recorded in run.json, nowhere else.
    const auto record = nlohmann::json::parse(read_file(out / "0000031337" / "run.json"));
    EXPECT_EQ(record.at("threads"), threads);
  }
  EXPECT_GT(files[0].size(), 40u);
  // The dataset card is compared too: it quotes no timings.
  for (const char* card : {"CARD.md", "card.json", "card_classes.png", "card_poses.png"}) EXPECT_EQ(files[0].count(card), 1u) << card;
  EXPECT_EQ(file_differences(files[0], files[1]), "");
}

}  // namespace
}  // namespace silva::test

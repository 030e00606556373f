// What `silva generate` prints: the --json summary, --quiet, progress lines and the live bar.
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>
#include <regex>

#include <nlohmann/json.hpp>

#include "silva_process.hpp"
#include "world/forest_types.hpp"
#include "world/trail_surface_choice.hpp"

namespace silva::test {
namespace {

namespace fs = std::filesystem;

TEST(GenerateOutput, JsonSummaryHoldsTheDocumentedFields) {
  const fs::path dir = fresh_test_dir();
  std::vector<std::string> args = tiny_run_args(dir / "out", 17);
  args.push_back("--json");
  const ProcessResult r = run_silva(args, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(lines_of(r.out).size(), 1u) << r.out;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("ok"), true);
  EXPECT_EQ(j.at("seed"), 17);
  EXPECT_EQ(j.at("run_dir"), (dir / "out" / "0000000017").string());
  EXPECT_EQ(j.at("frames_planned"), 5);
  EXPECT_EQ(j.at("frames_written"), 5);
  EXPECT_EQ(j.at("frames_skipped_complete"), 0);
  EXPECT_GT(j.at("bytes_written").get<double>(), 0);
  EXPECT_GT(j.at("wall_s").get<double>(), 0);
  EXPECT_GT(j.at("frames_per_s").get<double>(), 0);
  for (const char* phase : {"plan", "stream", "prepare", "render", "shadow", "shade", "encode", "write", "wall"})
    EXPECT_TRUE(j.at("timings_s").at(phase).is_number()) << phase;
  // bytes_written counts every frame file.
  uint64_t bytes = 0;
  for (const auto& [name, data] : folder_files(dir / "out" / "0000000017"))
    if (name.find('/') != std::string::npos) bytes += data.size();
  EXPECT_EQ(j.at("bytes_written").get<uint64_t>(), bytes);
  // The run record and manifest agree.
  const auto manifest = nlohmann::json::parse(read_file(dir / "out" / "0000000017" / "manifest.json"));
  EXPECT_EQ(manifest.at("frames"), nlohmann::json({{"autopilot", 3}, {"random", 2}}));
  EXPECT_EQ(manifest.at("seed"), 17);
  EXPECT_FALSE(manifest.at("config").at("output").contains("dir"));
}

TEST(GenerateOutput, TheCardNamesTheForestTypeAndTrailSurfaceARandomWorldDrew) {
  const fs::path dir = fresh_test_dir();
  std::vector<std::string> args = tiny_run_args(dir / "out", 19);
  args.insert(args.end(), {"--set", "vegetation.forest_type=random", "--set", "trail.surface=random"});
  const ProcessResult r = run_silva(args, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const fs::path run = dir / "out" / "0000000019";
  const auto card = nlohmann::json::parse(read_file(run / "card.json"));
  const std::string drawn = world::forest_type_of("random", 19).name;
  EXPECT_EQ(card.at("conditions").at("forest_type"), drawn);
  EXPECT_NE(drawn, "random");
  EXPECT_NE(read_file(run / "CARD.md").find("forest `" + drawn + "`"), std::string::npos);
  const std::string trail(trail_surface_name(world::trail_surface_of("random", 19)));
  EXPECT_EQ(card.at("conditions").at("trail_surface"), trail);
  EXPECT_NE(read_file(run / "CARD.md").find("trail `" + trail + "`"), std::string::npos);
}

TEST(GenerateOutput, QuietPrintsNothingOnSuccess) {
  const fs::path dir = fresh_test_dir();
  std::vector<std::string> args = tiny_run_args(dir / "out", 18);
  args.push_back("--quiet");
  const ProcessResult r = run_silva(args, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  // Without --json the one result line goes to stdout.
  ASSERT_EQ(lines_of(r.out).size(), 1u) << r.out;
  EXPECT_EQ(r.out.rfind("wrote 5 frames", 0), 0u) << r.out;
}

TEST(GenerateOutput, ProgressLinesWithoutATerminal) {
  const fs::path dir = fresh_test_dir();
  const ProcessResult r = run_silva(tiny_run_args(dir / "out", 19), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = lines_of(r.err);
  EXPECT_EQ(r.err.find('\r'), std::string::npos);
  ASSERT_GE(lines.size(), 3u) << r.err;
  EXPECT_EQ(lines[0], "silva: seed 0000000019");
  const std::regex progress(R"(silva: (\d+)/5 frames, \d+\.\d frames/s, ETA \d+ s)");
  int last = 0;
  for (const std::string& line : lines) {
    std::smatch m;
    if (!std::regex_match(line, m, progress)) continue;
    EXPECT_GT(std::stoi(m[1]), last);
    last = std::stoi(m[1]);
  }
  EXPECT_EQ(last, 5) << r.err;
}

TEST(GenerateOutput, LiveBarOnATerminal) {
  const fs::path dir = fresh_test_dir();
  std::vector<std::string> store = tiny_run_args(dir / "out", 20);
  store.insert(store.begin(), SILVA_BINARY);
  std::vector<char*> argv;
  for (std::string& a : store) argv.push_back(a.data());
  argv.push_back(nullptr);
  int master = -1;
  const pid_t pid = forkpty(&master, nullptr, nullptr, nullptr);
  if (pid < 0) {
    const int err = errno;
    GTEST_SKIP() << "no pseudo-terminal can be opened here (forkpty: " << std::strerror(err)
                 << "; e.g. a container or chroot without /dev/pts), so the live bar cannot be seen";
  }
  if (pid == 0) {
    ::execv(argv[0], argv.data());
    _exit(127);
  }
  std::string text;
  char buf[4096];
  for (ssize_t n; (n = ::read(master, buf, sizeof buf)) > 0;) text.append(buf, size_t(n));
  int status = 0;
  ::waitpid(pid, &status, 0);
  ::close(master);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << text;
  EXPECT_NE(text.find("\r[##############################] 5/5 frames"), std::string::npos) << text;
  EXPECT_NE(text.find("frames/s  ETA"), std::string::npos) << text;
  EXPECT_EQ(text.find("silva: 1/5 frames"), std::string::npos) << "no plain progress lines on a terminal";
}

}  // namespace
}  // namespace silva::test

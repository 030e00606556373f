// `silva generate --resume` after a SIGKILL at a seeded point equals an uninterrupted run.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <random>
#include <thread>

#include "io/atomic_file.hpp"
#include "silva_process.hpp"

namespace silva::test {
namespace {

namespace fs = std::filesystem;

constexpr int64_t kSeed = 4242;

/// Regular files below `dir` (0 when it does not exist yet).
size_t count_files(const fs::path& dir) {
  std::error_code ec;
  size_t n = 0;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec))
    n += it->is_regular_file(ec);
  return n;
}

/// Starts a run into `out` and SIGKILLs it once `files` files exist below its run folder, or
/// `ms` milliseconds after its marker appeared (loading and planning take longer on a loaded
/// machine), whichever comes first; returns how it ended.
ProcessResult kill_run(const fs::path& out, const fs::path& scratch, size_t files, int ms) {
  const ChildProcess child = start_silva(tiny_run_args(out, kSeed, kAllTypes), scratch);
  const fs::path run_dir = out / "0000004242";
  while (!fs::exists(run_dir / ".silva-run.json")) {
    if (::waitpid(child.pid, nullptr, WNOHANG) == child.pid) return {0, "", "finished before the kill"};
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(ms);
  while (count_files(run_dir) < files && std::chrono::steady_clock::now() < deadline) {
    if (::waitpid(child.pid, nullptr, WNOHANG) == child.pid) return {0, "", "finished before the kill"};
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ::kill(child.pid, SIGKILL);
  return wait_silva(child);
}

TEST(GenerateResume, ResumeAfterSigkillEqualsAnUninterruptedRun) {
  const fs::path dir = fresh_test_dir();
  const ProcessResult whole = run_silva(tiny_run_args(dir / "whole", kSeed, kAllTypes), dir);
  ASSERT_EQ(whole.code, 0) << whole.err;
  const auto expected = folder_files(dir / "whole" / "0000004242");
  ASSERT_GT(expected.size(), 40u);

  // Kill points from a fixed seed: by file count (inside the capture) and by time.
  std::mt19937 rng(20241123);
  const size_t files_to_kill_at[] = {1 + rng() % 8, 8 + rng() % (expected.size() - 16)};
  int round = 0;
  for (size_t files : files_to_kill_at) {
    SCOPED_TRACE("killed after " + std::to_string(files) + " files");
    const fs::path out = dir / ("killed" + std::to_string(round++));
    const ProcessResult killed = kill_run(out, dir, files, 60000);
    ASSERT_EQ(killed.code, 128 + SIGKILL) << killed.err;
    EXPECT_FALSE(fs::exists(out / "0000004242" / "manifest.json"));
    std::vector<std::string> resume = tiny_run_args(out, kSeed, kAllTypes);
    resume.push_back("--resume");
    const ProcessResult resumed = run_silva(resume, dir);
    ASSERT_EQ(resumed.code, 0) << resumed.err;
    EXPECT_TRUE(io::list_temp_files(out).empty());
    EXPECT_EQ(file_differences(folder_files(out / "0000004242"), expected), "");
  }
  // A kill after a seeded time, resumed without --seed (taken from the folder's marker).
  const fs::path out = dir / "killed_by_time";
  const ProcessResult killed = kill_run(out, dir, SIZE_MAX, 300 + int(rng() % 1500));
  EXPECT_TRUE(killed.code == 128 + SIGKILL || killed.code == 0) << killed.err;  // 0: done before the kill
  std::vector<std::string> resume = tiny_run_args(out, kSeed, kAllTypes);
  resume.erase(resume.begin() + 1, resume.begin() + 3);  // drop --seed N
  resume.push_back("--resume");
  const ProcessResult resumed = run_silva(resume, dir);
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  EXPECT_TRUE(io::list_temp_files(out).empty());
  EXPECT_EQ(file_differences(folder_files(out / "0000004242"), expected), "");
}

TEST(GenerateResume, SigintStopsCleanlyWithExit130AndResumes) {
  const fs::path dir = fresh_test_dir();
  const ChildProcess child = start_silva(tiny_run_args(dir / "out", kSeed), dir);
  const fs::path first_camera = dir / "out" / "0000004242" / "autopilot" / "camera" / "000000.json";
  while (!fs::exists(first_camera) && ::waitpid(child.pid, nullptr, WNOHANG) == 0)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  ::kill(child.pid, SIGINT);
  const ProcessResult stopped = wait_silva(child);
  if (stopped.code == 0) GTEST_SKIP() << "the run finished before the interrupt";
  ASSERT_EQ(stopped.code, 130) << stopped.err;
  EXPECT_NE(stopped.err.find("--resume"), std::string::npos) << stopped.err;
  std::vector<std::string> resume = tiny_run_args(dir / "out", kSeed);
  resume.push_back("--resume");
  const ProcessResult resumed = run_silva(resume, dir);
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  const ProcessResult whole = run_silva(tiny_run_args(dir / "whole", kSeed), dir);
  ASSERT_EQ(whole.code, 0) << whole.err;
  EXPECT_EQ(file_differences(folder_files(dir / "out" / "0000004242"), folder_files(dir / "whole" / "0000004242")), "");
}

}  // namespace
}  // namespace silva::test

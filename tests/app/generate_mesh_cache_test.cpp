// A run that reads its meshes from the mesh cache writes the same bytes as one that builds them, and a
// damaged cache is rebuilt rather than read.
#include <gtest/gtest.h>

#include "silva_process.hpp"
#include "tests/common/scoped_env.hpp"

namespace silva::test {
namespace {

namespace fs = std::filesystem;

/// Regular files under `dir` whose name ends in `ext`.
std::vector<fs::path> entries(const fs::path& dir, const std::string& ext) {
  std::vector<fs::path> out;
  if (!fs::exists(dir)) return out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ext) out.push_back(e.path());
  return out;
}

TEST(GenerateMeshCache, ColdWarmDamagedAndOffRunsWriteIdenticalFiles) {
  const fs::path dir = fresh_test_dir();
  const fs::path cache = dir / "cache";
  const auto run = [&](const std::string& name, const std::string& cache_setting) {
    const ScopedEnv env("SILVA_MESH_CACHE", cache_setting);
    const ProcessResult r = run_silva(tiny_run_args(dir / name, 4242, kAllTypes), dir);
    EXPECT_EQ(r.code, 0) << r.err;
    return folder_files(dir / name / "0000004242");
  };
  const auto cold = run("cold", cache.string());
  const std::vector<fs::path> lods = entries(cache, ".lods");
  ASSERT_GT(lods.size(), 10u);
  EXPECT_FALSE(entries(cache, ".mask").empty());
  const auto warm = run("warm", cache.string());
  EXPECT_EQ(file_differences(cold, warm), "");
  for (const fs::path& f : lods) fs::resize_file(f, fs::file_size(f) / 2);
  const auto damaged = run("damaged", cache.string());
  EXPECT_EQ(file_differences(cold, damaged), "");
  const auto off = run("off", "off");
  EXPECT_EQ(file_differences(cold, off), "");
  EXPECT_EQ(entries(cache, ".lods").size(), lods.size());
  EXPECT_GT(cold.size(), 40u);
}

}  // namespace
}  // namespace silva::test

#pragma once
/// @file Shared helpers for the io tests: scratch folders, OpenCV read-back, a synthetic G-buffer.
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "core/instance_id.hpp"
#include "io/atomic_file.hpp"
#include "io/label_planes.hpp"
#include "render/gbuffer.hpp"
#include "tests/common/scratch_dirs.hpp"

namespace silva::io::test {

/// A fresh, empty scratch folder named after the running test (removed and recreated; removed
/// again at the end of a test program whose tests all passed).
inline std::filesystem::path scratch_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("silva_io_test_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  silva::test::remove_when_passed(dir);
  return dir;
}

/// Writes bytes to dir/name and reads them back with cv::imread(IMREAD_UNCHANGED).
inline cv::Mat write_and_read(const std::filesystem::path& dir, const std::string& name,
                              const std::vector<uint8_t>& bytes) {
  static const bool exr_enabled = setenv("OPENCV_IO_ENABLE_OPENEXR", "1", 1) == 0;
  (void)exr_enabled;
  write_file_atomic(dir / name, bytes);
  return cv::imread((dir / name).string(), cv::IMREAD_UNCHANGED);
}

/// Reads a whole file as bytes.
inline std::vector<uint8_t> file_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

/// A renderer G-buffer that passes as the io LabelPlanes view of itself.
struct TestGBuffer : render::GBuffer {
  /// The planes io reads, viewing this buffer.
  operator LabelPlanes() const { return {width, height, depth, normal, role, instance_id}; }
};

/// A w x h G-buffer with every role, sky, varied depths (incl. > 65.535 m), tilted normals and
/// instance ids in runs, all from closed-form patterns.
inline TestGBuffer synthetic_gbuffer(int w = 53, int h = 37) {
  TestGBuffer g;
  g.resize(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      const int role = (x / 5 + y / 4) % kRoleCount;
      if (role == 0) continue;  // sky: depth 0, background, no instance
      g.role[i] = Role(role);
      g.depth[i] = 0.0004f + 0.37f * float(x * h + y) * (x % 3 == 0 ? 1.0f : 0.05f);
      const Vec3f n(std::sin(0.3f * x), std::cos(0.2f * y), 0.5f + 0.01f * x);
      g.normal[i] = n.normalized();
      if (role_has_instances(Role(role)))
        g.instance_id[i] = pack_instance_id(ChunkCoord{x / 11 - 2, y / 9}, uint32_t(1000 * role + 7 * (x / 7) + y / 6));
      else if (role == int(Role::TreeCanopy))
        g.instance_id[i] = pack_instance_id(ChunkCoord{0, 0}, 99);  // canopy: must not show in instance
    }
  return g;
}

}  // namespace silva::io::test

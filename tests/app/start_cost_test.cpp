// The `silva` binary starts without OpenCV's image codecs: they load GDAL and some 130 libraries, and
// io/ and assets/ open them at their first image instead (core/shared_library.hpp).
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>

namespace {

/// What `ldd` prints for `binary`: every shared library the loader maps at its start.
std::string libraries_at_start(const std::string& binary) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(("ldd '" + binary + "' 2>&1").c_str(), "r"), pclose);
  if (!pipe) return "";
  std::string out;
  char buffer[4096];
  for (size_t n; (n = fread(buffer, 1, sizeof(buffer), pipe.get())) > 0;) out.append(buffer, n);
  return out;
}

TEST(StartCost, SilvaLoadsNoImageCodecsAtStart) {
  const std::string libraries = libraries_at_start(SILVA_BINARY);
  ASSERT_NE(libraries.find("libopencv_core"), std::string::npos) << "ldd did not list the binary's libraries:\n"
                                                                  << libraries;
  EXPECT_EQ(libraries.find("libopencv_imgcodecs"), std::string::npos) << libraries;
  EXPECT_EQ(libraries.find("libgdal"), std::string::npos) << libraries;
}

}  // namespace

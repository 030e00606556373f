#pragma once
/// @file A user asset library of one textured OBJ triangle, for tests of texture reading.
#include <filesystem>
#include <fstream>
#include <string>

namespace silva::test {

/// Writes into `dir` (created) a library.json of one asset, a.obj: a triangle whose material
/// "photo" maps the texture file `texture` (not written here); returns library.json's path.
inline std::filesystem::path textured_obj_library(const std::filesystem::path& dir, const std::string& texture) {
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "a.obj") << "mtllib a.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                  "usemtl photo\nf 1/1 2/2 3/3\n";
  std::ofstream(dir / "a.mtl") << "newmtl photo\nKd 1 1 1\nmap_Kd " << texture << "\n";
  std::ofstream(dir / "library.json") << R"({"format": "silva-asset-library", "version": 1, "assets": [
    {"name": "a", "file": "a.obj", "kind": "rock", "class": "obstacle", "parts": {"photo": "obstacle"},
     "collision": {"shape": "sphere", "center": [0, 0, 1], "radius": 1}, "lod_screen_sizes": []}]})";
  return dir / "library.json";
}

}  // namespace silva::test

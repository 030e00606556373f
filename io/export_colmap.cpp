// COLMAP export (CONTRACT.md "Export formats"): a text model in sparse/0/. OpenCV camera axes and pixel
// centres at +0.5 are COLMAP's own, so K and the axes carry over unchanged; images.txt holds the
// world-to-camera rotation (quaternion w, x, y, z) and translation t = -Rᵀ·C. points3D.txt holds depth
// pixels on a grid (about 1000 per image) lifted to the world, each seen by its own image only.
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>

#include <Eigen/Geometry>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/export_formats.hpp"
#include "io/printf_string.hpp"

namespace silva::io {

namespace {

/// One depth pixel lifted into the world.
struct DepthPoint {
  double u = 0, v = 0;     ///< Pixel centre in COLMAP image coordinates.
  Vec3d x;                 ///< World position.
  cv::Vec3b bgr;           ///< Colour of the RGB pixel.
};

/// Lifts a grid of frame `f`'s depth pixels into the world.
std::vector<DepthPoint> frame_points(const Dataset& d, const DatasetFrame& f, const Camera& cam) {
  std::vector<DepthPoint> p;
  if (!d.has("depth") || !d.has("rgb")) return p;
  const cv::Mat depth = d.image(f, "depth", CV_16UC1);
  const cv::Mat rgb = d.image(f, "rgb", CV_8UC3);
  if (depth.cols != cam.width || depth.rows != cam.height)
    throw InputError(d.file(f, "depth", "png").string() + ": not the size its camera file gives");
  const int stride = std::max(1, int(std::lround(std::sqrt(double(cam.width) * cam.height / 1000.0))));
  const Mat3d r = cam.camera_to_world.block<3, 3>(0, 0);
  const Vec3d c = cam.camera_to_world.block<3, 1>(0, 3);
  for (int v = stride / 2; v < cam.height; v += stride)
    for (int u = stride / 2; u < cam.width; u += stride) {
      const uint16_t mm = depth.at<uint16_t>(v, u);
      if (mm == 0 || mm == 65535) continue;  // no hit, or beyond what the PNG holds
      const double z = mm / 1000.0;
      const Vec3d x = c + r * Vec3d(z * (u + 0.5 - cam.cx) / cam.fx, z * (v + 0.5 - cam.cy) / cam.fy, z);
      p.push_back({u + 0.5, v + 0.5, x, rgb.at<cv::Vec3b>(v, u)});
    }
  return p;
}

}  // namespace

void export_colmap(const Dataset& d, const std::filesystem::path& out, const ExportOptions& options) {
  d.require("rgb", "colmap");
  const std::filesystem::path model = out / "sparse" / "0";
  create_folder(out / "images");
  create_folder(model);
  std::vector<CameraRecord> records(d.frames.size());
  std::vector<std::vector<DepthPoint>> points(d.frames.size());
  for_each_frame(d, [&](size_t i) {
    const DatasetFrame& f = d.frames[i];
    place_file(d.file(f, "rgb", "png"), out / "images" / (f.stem() + ".png"), options);
    records[i] = read_camera_json(d.file(f, "camera", "json"));
    points[i] = frame_points(d, f, records[i].camera);
  });
  std::map<std::tuple<int, int, double, double, double, double>, int> camera_ids;
  std::string cameras = "# Camera list: CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[] (fx fy cx cy)\n";
  std::string images = "# Image list: IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n"
                       "#   then POINTS2D[] as (X, Y, POINT3D_ID)\n";
  std::string points3d = "# 3D point list: POINT3D_ID, X, Y, Z, R, G, B, ERROR, TRACK[] as (IMAGE_ID, POINT2D_IDX)\n";
  int next_point = 1;
  for (size_t i = 0; i < d.frames.size(); ++i) {
    const Camera& cam = records[i].camera;
    const auto key = std::make_tuple(cam.width, cam.height, cam.fx, cam.fy, cam.cx, cam.cy);
    auto [it, added] = camera_ids.emplace(key, int(camera_ids.size()) + 1);
    if (added)
      cameras += printf_string("%d PINHOLE %d %d %.17g %.17g %.17g %.17g\n", it->second, cam.width, cam.height, cam.fx,
                        cam.fy, cam.cx, cam.cy);
    const Mat3d r_wc = cam.camera_to_world.block<3, 3>(0, 0).transpose();
    const Vec3d t = -r_wc * cam.camera_to_world.block<3, 1>(0, 3);
    Eigen::Quaterniond q(r_wc);
    q.normalize();
    if (q.w() < 0) q.coeffs() = -q.coeffs();
    const int image_id = d.frames[i].global_index + 1;
    images += printf_string("%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %d ", image_id, q.w(), q.x(), q.y(), q.z(), t.x(),
                     t.y(), t.z(), it->second) +
              d.frames[i].stem() + ".png\n";
    std::string line2d;
    for (size_t k = 0; k < points[i].size(); ++k) {
      const DepthPoint& p = points[i][k];
      const int id = next_point++;
      points3d += printf_string("%d %.9g %.9g %.9g %d %d %d 0 %d %zu\n", id, p.x.x(), p.x.y(), p.x.z(), p.bgr[2], p.bgr[1],
                         p.bgr[0], image_id, k);
      line2d += printf_string(k ? " %.1f %.1f %d" : "%.1f %.1f %d", p.u, p.v, id);
    }
    images += line2d + "\n";
  }
  write_file_atomic(model / "cameras.txt", cameras);
  write_file_atomic(model / "images.txt", images);
  write_file_atomic(model / "points3D.txt", points3d);
}

}  // namespace silva::io

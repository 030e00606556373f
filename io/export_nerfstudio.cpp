// nerfstudio export (CONTRACT.md "Export formats"): transforms.json with OpenGL camera axes (x right,
// y up, looking down -z): transform_matrix = camera_to_world · diag(1, -1, -1, 1). Intrinsics are
// nerfstudio's pixel-centre convention (+0.5), the same as Silva's, so fl_x, fl_y, cx, cy carry over. depth/ holds
// the depth PNGs in millimetres (nerfstudio's default depth_unit_scale_factor 1e-3) with the clamped value 65535
// (anything at or beyond 65.535 m) written as 0, which nerfstudio's depth losses skip like a pixel without a hit.
#include "io/atomic_file.hpp"
#include "io/export_formats.hpp"
#include "io/png_writer.hpp"

namespace silva::io {

namespace {

/// A 4x4 matrix as a nested JSON list, row-major.
nlohmann::json matrix_json(const Mat4d& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < 4; ++r) rows.push_back({m(r, 0), m(r, 1), m(r, 2), m(r, 3)});
  return rows;
}

/// Mask of frame `f`: 255 where a surface was hit, 0 for the background class (sky).
void write_mask(const Dataset& d, const DatasetFrame& f, const std::filesystem::path& path) {
  const cv::Mat semantic = d.image(f, "semantic", CV_8UC1);
  const uint8_t sky = d.ontology.id(Role::Background);
  std::vector<uint8_t> mask(size_t(semantic.cols) * semantic.rows);
  for (int y = 0; y < semantic.rows; ++y)
    for (int x = 0; x < semantic.cols; ++x)
      mask[size_t(y) * semantic.cols + x] = semantic.at<uint8_t>(y, x) == sky ? 0 : 255;
  write_file_atomic(path, encode_png_grey8(mask, semantic.cols, semantic.rows));
}

/// Frame `f`'s depth PNG (millimetres) with the clamp value 65535 made 0 (no depth), so that no surface reads as
/// 65.535 m.
void write_depth(const Dataset& d, const DatasetFrame& f, const std::filesystem::path& path) {
  const cv::Mat mm = d.image(f, "depth", CV_16UC1);
  std::vector<uint16_t> depth(size_t(mm.cols) * mm.rows);
  for (int y = 0; y < mm.rows; ++y)
    for (int x = 0; x < mm.cols; ++x) {
      const uint16_t v = mm.at<uint16_t>(y, x);
      depth[size_t(y) * mm.cols + x] = v == 65535 ? 0 : v;
    }
  write_file_atomic(path, encode_png_grey16(depth, mm.cols, mm.rows));
}

}  // namespace

void export_nerfstudio(const Dataset& d, const std::filesystem::path& out, const ExportOptions& options) {
  d.require("rgb", "nerfstudio");
  const bool depth = d.has("depth"), masks = d.has("semantic");
  create_folder(out / "images");
  if (depth) create_folder(out / "depth");
  if (masks) create_folder(out / "masks");
  std::vector<CameraRecord> records(d.frames.size());
  std::vector<nlohmann::json> frames(d.frames.size());
  Mat4d flip = Mat4d::Identity();
  flip(1, 1) = flip(2, 2) = -1;
  for_each_frame(d, [&](size_t i) {
    const DatasetFrame& f = d.frames[i];
    const std::string name = f.stem() + ".png";
    place_file(d.file(f, "rgb", "png"), out / "images" / name, options);
    records[i] = read_camera_json(d.file(f, "camera", "json"));
    const Camera& c = records[i].camera;
    nlohmann::json frame = {{"file_path", "images/" + name},
                            {"transform_matrix", matrix_json(c.camera_to_world * flip)},
                            {"fl_x", c.fx}, {"fl_y", c.fy}, {"cx", c.cx}, {"cy", c.cy}, {"w", c.width},
                            {"h", c.height}};
    if (depth) {
      write_depth(d, f, out / "depth" / name);
      frame["depth_file_path"] = "depth/" + name;
    }
    if (masks) {
      write_mask(d, f, out / "masks" / name);
      frame["mask_path"] = "masks/" + name;
    }
    frame["sequence"] = f.sequence;
    frame["frame"] = f.frame;
    frames[i] = std::move(frame);
  });
  nlohmann::json transforms = {{"camera_model", "OPENCV"}, {"k1", 0}, {"k2", 0}, {"p1", 0}, {"p2", 0},
                               {"frames", frames}};
  if (!records.empty()) {
    const Camera& c = records.front().camera;
    transforms.update({{"fl_x", c.fx}, {"fl_y", c.fy}, {"cx", c.cx}, {"cy", c.cy}, {"w", c.width}, {"h", c.height}});
  }
  write_json(out / "transforms.json", transforms);
}

}  // namespace silva::io

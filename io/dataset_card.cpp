#include "io/dataset_card.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>

#include <opencv2/imgproc.hpp>

namespace silva::io {

namespace {

/// One frame's share of the counts.
CardCounts count_frame(const Dataset& d, const DatasetFrame& f) {
  CardCounts c;
  if (d.has("semantic")) {
    const cv::Mat semantic = read_image(d.file(f, "semantic", "png"), CV_8UC1);
    c.pixels = uint64_t(semantic.total());
    for (auto it = semantic.begin<uint8_t>(); it != semantic.end<uint8_t>(); ++it) ++c.class_pixels[*it];
  }
  if (d.has("instance")) {
    const cv::Mat instance = read_image(d.file(f, "instance", "png"), CV_16UC1);
    const std::vector<InstanceEntry> table = read_instance_table(d.file(f, "instance", "json"));
    std::vector<uint64_t> area(table.size() + 1, 0);
    for (auto it = instance.begin<uint16_t>(); it != instance.end<uint16_t>(); ++it)
      if (*it < area.size()) ++area[*it];
    for (const InstanceEntry& e : table) {
      if (!area[e.index]) continue;
      ++c.class_instances[e.class_id];
      ++c.instance_sizes[std::min(CardCounts::kSizeBins - 1, int(std::bit_width(area[e.index])) - 1)];
    }
  }
  if (d.has("depth")) {
    const cv::Mat depth = read_image(d.file(f, "depth", "png"), CV_16UC1);
    for (auto it = depth.begin<uint16_t>(); it != depth.end<uint16_t>(); ++it) {
      if (*it == 0) ++c.depth_no_hit;
      else ++c.depth[std::min(CardCounts::kDepthBins - 1, int(*it / 2000))];
    }
  }
  const CameraRecord cam = read_camera_json(d.file(f, "camera", "json"));
  c.positions.push_back(cam.camera.position());
  c.forwards.push_back(cam.camera.camera_to_world.block<3, 1>(0, 2));
  return c;
}

}  // namespace

CardCounts count_dataset(const Dataset& d) {
  std::vector<CardCounts> frames(d.frames.size());
  for_each_frame(d, [&](size_t i) { frames[i] = count_frame(d, d.frames[i]); });
  CardCounts total;
  std::map<std::string, int> sequences;
  for (size_t i = 0; i < frames.size(); ++i) {
    const CardCounts& c = frames[i];
    total.pixels += c.pixels;
    for (size_t k = 0; k < 256; ++k) total.class_pixels[k] += c.class_pixels[k];
    for (size_t k = 0; k < 256; ++k) total.class_instances[k] += c.class_instances[k];
    for (size_t k = 0; k < c.instance_sizes.size(); ++k) total.instance_sizes[k] += c.instance_sizes[k];
    for (size_t k = 0; k < c.depth.size(); ++k) total.depth[k] += c.depth[k];
    total.depth_no_hit += c.depth_no_hit;
    total.positions.push_back(c.positions.front());
    total.forwards.push_back(c.forwards.front());
    total.sequence_of.push_back(sequences.emplace(d.frames[i].sequence, int(sequences.size())).first->second);
  }
  return total;
}

std::vector<uint8_t> bar_chart(const std::string& title, const std::vector<std::string>& labels,
                               const std::vector<double>& values, const std::vector<std::array<uint8_t, 3>>& colors,
                               int width, int height) {
  cv::Mat img(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  const int left = 64, right = 10, top = 30, bottom = 100;
  cv::putText(img, title, {left, 20}, cv::FONT_HERSHEY_SIMPLEX, 0.5, {0, 0, 0}, 1, cv::LINE_AA);
  const double peak = std::max(1e-12, *std::max_element(values.begin(), values.end()));
  const int n = int(values.size()), plot_w = width - left - right, plot_h = height - top - bottom;
  cv::line(img, {left, top + plot_h}, {width - right, top + plot_h}, {0, 0, 0});
  cv::line(img, {left, top}, {left, top + plot_h}, {0, 0, 0});
  char peak_text[32];
  std::snprintf(peak_text, sizeof peak_text, peak >= 100 ? "%.0f" : "%.3g", peak);
  cv::putText(img, peak_text, {2, top + 10}, cv::FONT_HERSHEY_SIMPLEX, 0.35, {0, 0, 0}, 1, cv::LINE_AA);
  for (int i = 0; i < n; ++i) {
    const int x0 = left + plot_w * i / n + 1, x1 = left + plot_w * (i + 1) / n - 1;
    const int bar = int(std::lround(plot_h * values[size_t(i)] / peak));
    const auto& c = colors[size_t(i) % colors.size()];
    cv::rectangle(img, {x0, top + plot_h - bar}, {x1, top + plot_h}, cv::Scalar(c[0], c[1], c[2]), cv::FILLED);
    cv::rectangle(img, {x0, top + plot_h - bar}, {x1, top + plot_h}, {0, 0, 0});
    // Labels written upwards under their bar, ending at the axis.
    cv::Mat text(16, bottom - 4, CV_8UC3, cv::Scalar(255, 255, 255));
    int baseline = 0;
    const int text_w = cv::getTextSize(labels[size_t(i)], cv::FONT_HERSHEY_SIMPLEX, 0.35, 1, &baseline).width;
    cv::putText(text, labels[size_t(i)], {std::max(0, text.cols - 2 - text_w), 12}, cv::FONT_HERSHEY_SIMPLEX, 0.35,
                {0, 0, 0}, 1, cv::LINE_AA);
    cv::Mat turned;
    cv::rotate(text, turned, cv::ROTATE_90_COUNTERCLOCKWISE);
    const int cx = std::clamp((x0 + x1) / 2 - 8, 0, width - 16);
    turned.copyTo(img(cv::Rect(cx, top + plot_h + 2, 16, bottom - 4)));
  }
  return std::vector<uint8_t>(img.data, img.data + img.total() * 3);
}

std::vector<uint8_t> pose_map(const CardCounts& counts, const std::vector<std::array<uint8_t, 3>>& sequence_colors,
                              int size) {
  cv::Mat img(size, size, CV_8UC3, cv::Scalar(255, 255, 255));
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const Vec3d& p : counts.positions)
    x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
  const double span = std::max({x1 - x0, y1 - y0, 1.0}) * 1.1, mx = (x0 + x1) / 2, my = (y0 + y1) / 2;
  const double scale = (size - 40) / span;
  const auto to_px = [&](double x, double y) {
    return cv::Point(int(std::lround(size / 2 + (x - mx) * scale)), int(std::lround(size / 2 - (y - my) * scale)));
  };
  char legend[64];
  std::snprintf(legend, sizeof legend, "camera positions, top down (%.0f m across)", span);
  cv::putText(img, legend, {8, 16}, cv::FONT_HERSHEY_SIMPLEX, 0.45, {0, 0, 0}, 1, cv::LINE_AA);
  for (size_t i = 0; i < counts.positions.size(); ++i) {
    const Vec3d& p = counts.positions[i];
    Vec3d f = counts.forwards[i];
    f.z() = 0;
    if (f.norm() > 0) f.normalize();
    const auto& c = sequence_colors[size_t(counts.sequence_of[i]) % sequence_colors.size()];
    const cv::Scalar color(c[0], c[1], c[2]);
    const cv::Point a = to_px(p.x(), p.y());
    cv::line(img, a, a + cv::Point(int(std::lround(f.x() * 12)), int(std::lround(-f.y() * 12))), color, 1, cv::LINE_AA);
    cv::circle(img, a, 3, color, cv::FILLED, cv::LINE_AA);
  }
  return std::vector<uint8_t>(img.data, img.data + img.total() * 3);
}

}  // namespace silva::io

#include "io/dataset_card.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <map>
#include <span>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "io/json_read.hpp"

namespace silva::io {

namespace {

/// Adds the class ids of a semantic image.
void count_semantic(std::span<const uint8_t> ids, CardCounts& c) {
  c.pixels += ids.size();
  for (uint8_t id : ids) ++c.class_pixels[id];
}

/// Adds the instances (with pixels) of an instance image and its table.
void count_instances(std::span<const uint16_t> index, const std::vector<InstanceEntry>& table, CardCounts& c) {
  std::vector<uint64_t> area(table.size() + 1, 0);
  for (uint16_t i : index)
    if (i < area.size()) ++area[i];
  for (const InstanceEntry& e : table) {
    if (!area[e.index]) continue;
    ++c.class_instances[e.class_id];
    ++c.instance_sizes[std::min(CardCounts::kSizeBins - 1, int(std::bit_width(area[e.index])) - 1)];
  }
}

/// Adds one depth value (millimetres, 0 = no hit) to the histogram.
void count_depth(uint16_t mm, CardCounts& c) {
  if (mm == 0) ++c.depth_no_hit;
  else ++c.depth[std::min(CardCounts::kDepthBins - 1, int(mm / 2000))];
}

/// The pixels of a one-channel image as a span.
template <class T>
std::span<const T> pixels(const cv::Mat& image) {
  return {image.ptr<T>(), image.total()};
}

/// One frame's label counts, read from its PNGs.
CardCounts count_frame_files(const Dataset& d, const DatasetFrame& f) {
  CardCounts c;
  if (d.has("semantic")) count_semantic(pixels<uint8_t>(d.image(f, "semantic", CV_8UC1)), c);
  if (d.has("instance"))
    count_instances(pixels<uint16_t>(d.image(f, "instance", CV_16UC1)),
                    read_instance_table(d.file(f, "instance", "json")), c);
  if (d.has("depth")) {
    const cv::Mat depth = d.image(f, "depth", CV_16UC1);  // a temporary would die before the loop
    for (uint16_t mm : pixels<uint16_t>(depth)) count_depth(mm, c);
  }
  if (d.has("lidar")) {
    const std::vector<uint32_t> labels = d.lidar_labels(f);
    for (const uint32_t label : labels) ++c.lidar_class_points[label & 0xFFFFu];
    c.lidar_points = labels.size();
  }
  return c;
}

}  // namespace

void add_label_counts(CardCounts& into, const CardCounts& other) {
  into.pixels += other.pixels;
  for (size_t k = 0; k < 256; ++k) into.class_pixels[k] += other.class_pixels[k];
  for (size_t k = 0; k < 256; ++k) into.class_instances[k] += other.class_instances[k];
  for (size_t k = 0; k < other.instance_sizes.size(); ++k) into.instance_sizes[k] += other.instance_sizes[k];
  for (size_t k = 0; k < other.depth.size(); ++k) into.depth[k] += other.depth[k];
  into.depth_no_hit += other.depth_no_hit;
  into.lidar_points += other.lidar_points;
  for (size_t k = 0; k < 256; ++k) into.lidar_class_points[k] += other.lidar_class_points[k];
}

CardCounts count_planes(const LabelPlanes& g, std::span<const LidarPoint> lidar, const Ontology& ontology,
                        bool semantic, bool instance, bool depth, bool lidar_selected) {
  CardCounts c;
  if (lidar_selected) {
    c.lidar_points = lidar.size();
    for (const LidarPoint& p : lidar) ++c.lidar_class_points[ontology.id(p.role)];
  }
  if (semantic) {
    c.pixels = g.size();
    for (Role r : g.role) ++c.class_pixels[ontology.id(r)];
  }
  if (instance) {
    const InstanceImage image = instance_image(g, ontology);
    count_instances(image.pixels, image.entries, c);
  }
  if (depth)
    for (float z : g.depth) count_depth(depth_to_mm(z), c);
  return c;
}

CardCounts count_dataset(const Dataset& d, const KnownCounts& known) {
  std::vector<CardCounts> frames(d.frames.size());
  for_each_frame(d, [&](size_t i) {
    const DatasetFrame& f = d.frames[i];
    if (!known.frames.count({f.sequence, f.frame})) frames[i] = count_frame_files(d, f);
    const CameraRecord cam = read_camera_json(d.file(f, "camera", "json"));
    frames[i].positions.push_back(cam.camera.position());
    frames[i].forwards.push_back(cam.camera.camera_to_world.block<3, 1>(0, 2));
  });
  CardCounts total;
  add_label_counts(total, known.totals);
  std::map<std::string, int> sequences;
  for (size_t i = 0; i < frames.size(); ++i) {
    const CardCounts& c = frames[i];
    add_label_counts(total, c);
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

int pose_map_width(int size, const std::vector<LegendEntry>& legend) { return size + (legend.empty() ? 0 : 150); }

std::vector<uint8_t> pose_map(const CardCounts& counts, const std::vector<std::array<uint8_t, 3>>& sequence_colors,
                              int size, const MapBackground* map, const std::vector<LegendEntry>& legend) {
  cv::Mat img(size, pose_map_width(size, legend), CV_8UC3, cv::Scalar(255, 255, 255));
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  if (map) {
    x0 = map->x0, x1 = map->x0 + map->width * map->metres_per_pixel;
    y1 = map->y1, y0 = map->y1 - map->height * map->metres_per_pixel;
  } else {
    for (const Vec3d& p : counts.positions)
      x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
  }
  const double span = std::max({x1 - x0, y1 - y0, 1.0}) * (map ? 1.0 : 1.1), mx = (x0 + x1) / 2, my = (y0 + y1) / 2;
  const double scale = (size - 40) / span, half = 0.5 * size;
  const auto to_px = [&](double x, double y) {
    return cv::Point(int(std::lround(half + (x - mx) * scale)), int(std::lround(half - (y - my) * scale)));
  };
  if (map)
    for (int r = 20; r < size - 20; ++r)
      for (int c = 20; c < size - 20; ++c) {
        const double x = mx + (c + 0.5 - half) / scale, y = my - (r + 0.5 - half) / scale;
        const int mc = int(std::floor((x - map->x0) / map->metres_per_pixel));
        const int mr = int(std::floor((map->y1 - y) / map->metres_per_pixel));
        if (mc < 0 || mr < 0 || mc >= map->width || mr >= map->height) continue;
        const uint8_t* rgb = &map->rgb[(size_t(mr) * size_t(map->width) + size_t(mc)) * 3];
        img.at<cv::Vec3b>(r, c) = cv::Vec3b(rgb[0], rgb[1], rgb[2]);
      }
  char title[96];
  std::snprintf(title, sizeof title, map ? "cameras over the class map, top down (%.0f m across)"
                                         : "camera positions, top down (%.0f m across)", span);
  cv::putText(img, title, {8, 15}, cv::FONT_HERSHEY_SIMPLEX, 0.45, {0, 0, 0}, 1, cv::LINE_AA);
  for (size_t i = 0; i < counts.positions.size(); ++i) {
    const Vec3d& p = counts.positions[i];
    Vec3d f = counts.forwards[i];
    f.z() = 0;
    if (f.norm() > 0) f.normalize();
    const auto& c = sequence_colors[size_t(counts.sequence_of[i]) % sequence_colors.size()];
    const cv::Scalar color(c[0], c[1], c[2]), white(255, 255, 255);
    const cv::Point a = to_px(p.x(), p.y());
    const cv::Point b = a + cv::Point(int(std::lround(f.x() * 12)), int(std::lround(-f.y() * 12)));
    cv::line(img, a, b, white, 3, cv::LINE_AA);
    cv::circle(img, a, 4, white, cv::FILLED, cv::LINE_AA);
    cv::line(img, a, b, color, 1, cv::LINE_AA);
    cv::circle(img, a, 3, color, cv::FILLED, cv::LINE_AA);
  }
  for (size_t k = 0; k < legend.size(); ++k) {
    const int y = 40 + int(k) * 18;
    const auto& c = legend[k].second;
    cv::rectangle(img, {size + 4, y - 10}, {size + 16, y + 2}, cv::Scalar(c[0], c[1], c[2]), cv::FILLED);
    cv::rectangle(img, {size + 4, y - 10}, {size + 16, y + 2}, {0, 0, 0});
    cv::putText(img, legend[k].first, {size + 22, y}, cv::FONT_HERSHEY_SIMPLEX, 0.4, {0, 0, 0}, 1, cv::LINE_AA);
  }
  return std::vector<uint8_t>(img.data, img.data + img.total() * 3);
}

}  // namespace silva::io

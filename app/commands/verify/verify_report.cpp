// `silva verify`'s certificate (see verify_report.hpp).
#include "app/commands/verify/verify_report.hpp"

#include <cstdio>

#include "pipeline/console/version.hpp"
#include "io/run_folder.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

namespace {

/// a / b, 1 when b is 0 (nothing to disagree with).
double share(uint64_t a, uint64_t b) { return b ? double(a) / double(b) : 1.0; }

/// A share as "99.9876 %".
std::string percent(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f %%", 100.0 * s);
  return buf;
}

/// A number with 3 significant digits ("1.23e-05", "0.0123").
std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

/// {"p50", "p99", "p99_9", "max"} of a histogram.
nlohmann::json percentiles(const ErrorHistogram& h) {
  return {{"p50", h.quantile(0.5)}, {"p99", h.quantile(0.99)}, {"p99_9", h.quantile(0.999)}, {"max", h.max}};
}

/// Name of class id `id` in the dataset's ontology (the first role with it), or the id.
std::string class_name(const Ontology& o, int id) {
  for (const OntologyClass& c : o.classes)
    if (c.id == id) return c.name;
  return std::to_string(id);
}

}  // namespace

nlohmann::json tally_summary(const VerifyTally& t, bool instances) {
  const auto [ip, ia] = t.interior.total();
  const auto [sp, sa] = t.silhouette.total();
  nlohmann::json examples = nlohmann::json::array();
  for (const PixelDisagreement& e : t.examples)
    examples.push_back({{"x", e.x}, {"y", e.y}, {"interior", e.interior}, {"file_class", e.file_class},
                        {"ray_class", e.ray_class}, {"file_depth_m", e.file_depth}, {"ray_depth_m", e.ray_depth}});
  return {{"pixels", ip + sp},
          {"class_interior", share(ia, ip)},
          {"class_silhouette", share(sa, sp)},
          {"depth_within", share(t.depth_within, t.depth_hit)},
          {"instance_interior", instances ? nlohmann::json(share(t.instance_agree, t.instance_pixels)) : nlohmann::json()},
          {"examples", examples}};
}

nlohmann::json verify_json(const io::Dataset& d, const VerifyRequest& r, const VerifyCounts& c) {
  const VerifyTally& t = c.pixels;
  const auto [ip, ia] = t.interior.total();
  const auto [sp, sa] = t.silhouette.total();
  nlohmann::json by_class = nlohmann::json::array();
  for (int id = 0; id < 256; ++id) {
    const size_t k = size_t(id);
    if (t.interior.pixels[k] + t.silhouette.pixels[k] + t.depth_hit_by_class[k] == 0) continue;
    by_class.push_back({{"id", id},
                        {"name", class_name(d.ontology, id)},
                        {"interior_pixels", t.interior.pixels[k]},
                        {"interior_agreement", share(t.interior.agree[k], t.interior.pixels[k])},
                        {"silhouette_pixels", t.silhouette.pixels[k]},
                        {"silhouette_agreement", share(t.silhouette.agree[k], t.silhouette.pixels[k])},
                        {"depth_hit_pixels", t.depth_hit_by_class[k]},
                        {"depth_within", share(t.depth_within_by_class[k], t.depth_hit_by_class[k])}});
  }
  nlohmann::json confusion = nlohmann::json::array();
  for (const auto& [k, n] : t.confusion)
    confusion.push_back({{"file_class", k.first}, {"ray_class", k.second}, {"pixels", n}});
  const double class_interior = share(ia, ip), depth_within = share(t.depth_within, t.depth_hit);
  const bool class_ok = 100.0 * class_interior >= r.min_class, depth_ok = 100.0 * depth_within >= r.min_depth;
  nlohmann::json lidar;
  if (c.lidar) {
    const LidarTally& l = *c.lidar;
    lidar = {{"points", l.points},
             {"in_view", l.in_view},
             {"compared", l.compared},
             {"hidden_from_camera", l.hidden},
             {"class_agreement", share(l.class_agree, l.compared)},
             {"range_error_m", percentiles(l.range_error_m)}};
  }
  return {{"silva_version", silva_version()},
          {"seed", d.seed},
          {"frames_in_dataset", d.frames.size()},
          {"frames_checked", c.frames.size()},
          {"render_lod", d.manifest.at("config").at("render").at("lod")},
          {"geometry", d.manifest.at("config").at("render").at("lod").get<bool>() && !r.full_detail ? "as_drawn"
                                                                                                  : "full_detail"},
          {"sample", r.sample},
          {"pixels", ip + sp},
          {"thresholds",
           {{"class_interior_percent", r.min_class},
            {"depth_within_percent", r.min_depth},
            {"depth_tolerance_percent", r.depth_tolerance}}},
          {"class",
           {{"interior", {{"pixels", ip}, {"agreement", class_interior}}},
            {"silhouette", {{"pixels", sp}, {"agreement", share(sa, sp)}}},
            {"by_class", by_class},
            {"interior_confusion", confusion}}},
          {"instance", c.instances ? nlohmann::json{{"interior_pixels", t.instance_pixels},
                                                    {"interior_agreement", share(t.instance_agree, t.instance_pixels)}}
                                   : nlohmann::json()},
          {"depth",
           {{"source", c.depth_source},
            {"hit_pixels", t.depth_hit},
            {"within_tolerance", depth_within},
            {"file_only", t.depth_only_file},
            {"ray_only", t.depth_only_ray},
            {"relative_error", percentiles(t.depth_error)}}},
          {"normal", c.normals ? nlohmann::json{{"pixels", t.normal_error_deg.count},
                                                {"angle_error_deg", percentiles(t.normal_error_deg)}}
                               : nlohmann::json()},
          {"lidar", lidar},
          {"frames", c.frames},
          {"verdict", {{"pass", class_ok && depth_ok}, {"class_interior", class_ok}, {"depth", depth_ok}}}};
}

namespace {

/// VERIFY.md's opening: verdict, what was done, the thresholds table.
std::string markdown_verdict(const nlohmann::json& v) {
  const nlohmann::json& th = v["thresholds"];
  const nlohmann::json& cls = v["class"];
  const nlohmann::json& verdict = v["verdict"];
  const auto pass = [](bool ok) { return ok ? std::string("pass") : std::string("**FAIL**"); };
  std::string md = "# Label certificate of Silva dataset " + io::seed_folder_name(v["seed"].get<int64_t>()) + "\n\n";
  md += "**Verdict: " + std::string(verdict["pass"].get<bool>() ? "PASS" : "FAIL") + "**. `silva verify` (Silva " +
        v["silva_version"].get<std::string>() + ") rebuilt the world of " +
        std::to_string(v["frames_checked"].get<size_t>()) + " of the dataset's " +
        std::to_string(v["frames_in_dataset"].get<size_t>()) +
        " frames from its manifest and cast a ray through the centre of " + percent(v["sample"].get<double>()) +
        " of each frame's pixels (" + std::to_string(v["pixels"].get<uint64_t>()) +
        " pixels) with the Embree ray caster, independently of the rasteriser that wrote the files, "
        "then compared the hits with the files.\n\n";
  md += "| check | threshold | measured | result |\n|---|---|---|---|\n";
  md += "| class agreement, interior pixels | ≥ " + number(th["class_interior_percent"].get<double>()) + " % | " +
        percent(cls["interior"]["agreement"].get<double>()) + " | " + pass(verdict["class_interior"].get<bool>()) + " |\n";
  md += "| hit pixels with depth within " + number(th["depth_tolerance_percent"].get<double>()) + " % | ≥ " +
        number(th["depth_within_percent"].get<double>()) + " % | " +
        percent(v["depth"]["within_tolerance"].get<double>()) + " | " + pass(verdict["depth"].get<bool>()) + " |\n\n";
  if (v["render_lod"].get<bool>() && v["geometry"] == "as_drawn")
    md += "The dataset was rendered with `render.lod = true`: the rays met every instance at the level the "
          "rasteriser drew for that frame (the terrain's coarse level beyond about 34 m, assets by their size on "
          "screen), so this certifies the files against the triangles they show. `silva verify --full-detail` casts "
          "full detail instead and measures how far the coarser levels move depth.\n\n";
  else if (v["render_lod"].get<bool>())
    md += "The dataset was rendered with `render.lod = true` and checked at full detail (`--full-detail`): what the "
          "rasteriser drew at a coarser level has the labels of full detail but differs from the full-detail world "
          "in depth by its simplification error, which the depth check counts; `render.lod = false` renders full "
          "detail everywhere.\n\n";
  md += "Interior pixels are those whose 3×3 neighbourhood holds one class in the semantic PNG; the others are "
        "silhouette pixels, reported apart (a sub-pixel edge or an alpha texel boundary may fall on either side "
        "of a pixel centre). Class agreement at silhouettes: " +
        percent(cls["silhouette"]["agreement"].get<double>()) + " of " +
        std::to_string(cls["silhouette"]["pixels"].get<uint64_t>()) + " pixels.\n\n";
  return md;
}

/// VERIFY.md's per-class table and interior disagreements.
std::string markdown_classes(const nlohmann::json& cls) {
  std::string md = "## Classes\n\n| id | class | interior pixels | interior agreement | silhouette pixels | "
                   "silhouette agreement | depth within tolerance, of hit pixels |\n|---|---|---|---|---|---|---|\n";
  for (const auto& row : cls["by_class"])
    md += "| " + std::to_string(row["id"].get<int>()) + " | " + row["name"].get<std::string>() + " | " +
          std::to_string(row["interior_pixels"].get<uint64_t>()) + " | " +
          percent(row["interior_agreement"].get<double>()) + " | " +
          std::to_string(row["silhouette_pixels"].get<uint64_t>()) + " | " +
          percent(row["silhouette_agreement"].get<double>()) + " | " + percent(row["depth_within"].get<double>()) +
          " of " + std::to_string(row["depth_hit_pixels"].get<uint64_t>()) + " |\n";
  if (!cls["interior_confusion"].empty()) {
    md += "\nInterior disagreements (class in the file → class the ray caster hit: pixels):";
    for (const auto& e : cls["interior_confusion"])
      md.append(" ").append(std::to_string(e["file_class"].get<int>())).append(" → ")
          .append(std::to_string(e["ray_class"].get<int>())).append(": ")
          .append(std::to_string(e["pixels"].get<uint64_t>())).append(";");
    md.back() = '.';
    md += "\n";
  }
  return md;
}

/// VERIFY.md's depth, instance and normal paragraphs.
std::string markdown_depth(const nlohmann::json& v) {
  const nlohmann::json& depth = v["depth"];
  const nlohmann::json& rel = depth["relative_error"];
  std::string md = "\n## Depth\n\nFrom the `" + depth["source"].get<std::string>() +
                   "` images; relative error |z_ray − z_file| / z_file where both hit: p50 " + number(rel["p50"].get<double>()) +
                   ", p99 " + number(rel["p99"].get<double>()) + ", p99.9 " + number(rel["p99_9"].get<double>()) +
                   ", max " + number(rel["max"].get<double>()) + ". " + std::to_string(depth["hit_pixels"].get<uint64_t>()) +
                   " hit pixels; " + std::to_string(depth["file_only"].get<uint64_t>()) +
                   " hold a depth where the ray hit nothing, " + std::to_string(depth["ray_only"].get<uint64_t>()) +
                   " hold none where the ray hit a surface.\n";
  if (!v["instance"].is_null())
    md += "\n## Instances\n\nSame packed instance id on " +
          percent(v["instance"]["interior_agreement"].get<double>()) + " of " +
          std::to_string(v["instance"]["interior_pixels"].get<uint64_t>()) + " interior pixels.\n";
  if (!v["normal"].is_null()) {
    const nlohmann::json& a = v["normal"]["angle_error_deg"];
    md += "\n## Normals\n\nAngle between the normal PNG's normal and the ray caster's interpolated normal, where "
          "both agree on class and depth (" + std::to_string(v["normal"]["pixels"].get<uint64_t>()) +
          " pixels; the PNG's 8 bits per axis alone allow about 0.5°): p50 " + number(a["p50"].get<double>()) +
          "°, p99 " + number(a["p99"].get<double>()) + "°, p99.9 " + number(a["p99_9"].get<double>()) + "°, max " +
          number(a["max"].get<double>()) + "°.\n";
  }
  return md;
}

/// VERIFY.md's LiDAR paragraph ("" without LiDAR).
std::string markdown_lidar(const nlohmann::json& l) {
  if (l.is_null()) return "";
  const nlohmann::json& e = l["range_error_m"];
  return "\n## LiDAR against the depth files\n\nOf " + std::to_string(l["points"].get<uint64_t>()) + " points, " +
         std::to_string(l["in_view"].get<uint64_t>()) + " project into the camera image; " +
         std::to_string(l["compared"].get<uint64_t>()) + " land on interior pixels and are seen by the camera (" +
         std::to_string(l["hidden_from_camera"].get<uint64_t>()) +
         " more are hidden from it, seen from the LiDAR's mount). Their label class is the semantic PNG's on " +
         percent(l["class_agreement"].get<double>()) +
         "; range along the camera ray minus the depth file's (range noise included): p50 " +
         number(e["p50"].get<double>()) + " m, p99 " + number(e["p99"].get<double>()) + " m, max " +
         number(e["max"].get<double>()) + " m.\n";
}

/// VERIFY.md's per-frame table and each frame's largest disagreements.
std::string markdown_frames(const nlohmann::json& frames) {
  std::string md = "\n## Frames\n\n| frame | pixels | class (interior) | class (silhouette) | depth within tolerance |\n"
                   "|---|---|---|---|---|\n";
  bool any_example = false;
  for (const auto& f : frames) {
    md += "| " + f["sequence"].get<std::string>() + " " + std::to_string(f["frame"].get<int>()) + " | " +
          std::to_string(f["pixels"].get<uint64_t>()) + " | " + percent(f["class_interior"].get<double>()) + " | " +
          percent(f["class_silhouette"].get<double>()) + " | " + percent(f["depth_within"].get<double>()) + " |\n";
    any_example = any_example || !f["examples"].empty();
  }
  if (!any_example) return md;
  md += "\n## Largest disagreements\n\n| frame | pixel (x, y) | interior | class file → ray | depth file → ray (m) "
        "|\n|---|---|---|---|---|\n";
  for (const auto& f : frames)
    for (const auto& e : f["examples"])
      md += "| " + f["sequence"].get<std::string>() + " " + std::to_string(f["frame"].get<int>()) + " | " +
            std::to_string(e["x"].get<int>()) + ", " + std::to_string(e["y"].get<int>()) + " | " +
            (e["interior"].get<bool>() ? "yes" : "no") + " | " + std::to_string(e["file_class"].get<int>()) +
            " → " + std::to_string(e["ray_class"].get<int>()) + " | " + number(e["file_depth_m"].get<double>()) +
            " → " + number(e["ray_depth_m"].get<double>()) + " |\n";
  return md;
}

}  // namespace

std::string verify_markdown(const nlohmann::json& v) {
  return markdown_verdict(v) + markdown_classes(v["class"]) + markdown_depth(v) + markdown_lidar(v["lidar"]) +
         markdown_frames(v["frames"]);
}

}  // namespace silva::app

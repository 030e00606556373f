#include "bench/harness/profile_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "io/png_writer.hpp"

namespace silva::bench {

namespace {

/// The nearest-neighbour figures as JSON (null for fewer than 2 objects).
nlohmann::json nearest_json(const std::optional<NearestStats>& n) {
  if (!n) return nullptr;
  return {{"min", n->min}, {"p10", n->p10}, {"median", n->median}, {"p90", n->p90}};
}

/// The whole-world figures as JSON.
nlohmann::json world_json(const WorldProfile& w) {
  return {{"chunks", w.chunks},
          {"area_ha", w.area_ha},
          {"objects", w.objects},
          {"candidates", w.candidates},
          {"canopy_cover_pct", w.canopy_cover_pct},
          {"fcl_broad_queries", w.broad_queries},
          {"fcl_narrow_queries", w.narrow_queries},
          {"generate_ms_per_chunk", w.generate_ms_per_chunk},
          {"place_ms_per_chunk", w.place_ms_per_chunk},
          {"resolve_ms_per_chunk", w.resolve_ms_per_chunk},
          {"build_s", w.build_s}};
}

/// Adds every number of `add` into `sum` (same shape; nulls stay null in a null sum).
void add_numbers(nlohmann::json& sum, const nlohmann::json& add) {
  if (sum.is_null()) {
    sum = add;
    return;
  }
  if (sum.is_object() && add.is_object()) {
    for (auto& [k, v] : add.items()) add_numbers(sum[k], v);
  } else if (sum.is_number() && add.is_number()) {
    sum = sum.get<double>() + add.get<double>();
  }
}

/// Divides every number of `j` by n.
void divide_numbers(nlohmann::json& j, double n) {
  if (j.is_object())
    for (auto& [k, v] : j.items()) divide_numbers(v, n);
  else if (j.is_number())
    j = j.get<double>() / n;
}

}  // namespace

nlohmann::json sample_json(const ProfileSample& s, const Ontology& ontology) {
  nlohmann::json classes = nlohmann::json::object();
  for (int r = 0; r < kRoleCount; ++r) {
    const ClassProfile& c = s.world.classes[size_t(r)];
    if (!c.candidates && !c.placed) continue;
    classes[ontology.classes[size_t(r)].name] = {{"candidates", c.candidates}, {"placed", c.placed},
                                                 {"adjusted", c.adjusted},     {"dropped", c.dropped},
                                                 {"per_ha", c.per_ha},         {"cover_pct", c.cover_pct},
                                                 {"nearest_m", nearest_json(c.nearest)}};
  }
  return {{"density", s.density}, {"max_elevation", s.max_elevation}, {"trail", s.trail},
          {"seed", s.seed},       {"world", world_json(s.world)},     {"classes", classes}};
}

nlohmann::json sweep_means(const std::vector<ProfileSample>& samples, const Ontology& ontology) {
  nlohmann::json out = nlohmann::json::array();
  std::vector<bool> used(samples.size(), false);
  for (size_t a = 0; a < samples.size(); ++a) {
    if (used[a]) continue;
    nlohmann::json sum, seeds = nlohmann::json::array();
    int n = 0;
    for (size_t b = a; b < samples.size(); ++b) {
      const ProfileSample &x = samples[a], &y = samples[b];
      if (used[b] || x.density != y.density || x.max_elevation != y.max_elevation || x.trail != y.trail) continue;
      used[b] = true;
      nlohmann::json j = sample_json(y, ontology);
      seeds.push_back(y.seed);
      add_numbers(sum, {{"world", j["world"]}, {"classes", j["classes"]}});
      ++n;
    }
    divide_numbers(sum, n);
    out.push_back({{"density", samples[a].density}, {"max_elevation", samples[a].max_elevation},
                   {"trail", samples[a].trail}, {"seeds", seeds}, {"world", sum["world"]}, {"classes", sum["classes"]}});
  }
  return out;
}

std::string samples_csv(const std::vector<ProfileSample>& samples, const Ontology& ontology) {
  std::ostringstream csv;
  csv << "density,max_elevation,trail,seed,class,candidates,placed,adjusted,dropped,per_ha,cover_pct,"
         "nn_min_m,nn_p10_m,nn_median_m,nn_p90_m,area_ha,canopy_cover_pct,fcl_broad_queries,fcl_narrow_queries,"
         "generate_ms_per_chunk,place_ms_per_chunk,resolve_ms_per_chunk,build_s\n";
  char line[512];
  for (const ProfileSample& s : samples) {
    for (int r = 0; r < kRoleCount; ++r) {
      const ClassProfile& c = s.world.classes[size_t(r)];
      if (!c.candidates && !c.placed) continue;
      const NearestStats nn = c.nearest.value_or(NearestStats{});
      const WorldProfile& w = s.world;
      std::snprintf(line, sizeof line,
                    "%g,%g,%s,%lld,%s,%llu,%llu,%llu,%llu,%.3f,%.3f,%s,%s,%s,%s,%.4f,%.3f,%llu,%llu,%.4f,%.4f,%.4f,%.4f\n",
                    s.density, s.max_elevation, s.trail ? "on" : "off", static_cast<long long>(s.seed),
                    ontology.classes[size_t(r)].name.c_str(), (unsigned long long)c.candidates,
                    (unsigned long long)c.placed, (unsigned long long)c.adjusted, (unsigned long long)c.dropped,
                    c.per_ha, c.cover_pct, c.nearest ? std::to_string(nn.min).c_str() : "",
                    c.nearest ? std::to_string(nn.p10).c_str() : "", c.nearest ? std::to_string(nn.median).c_str() : "",
                    c.nearest ? std::to_string(nn.p90).c_str() : "", w.area_ha, w.canopy_cover_pct,
                    (unsigned long long)w.broad_queries, (unsigned long long)w.narrow_queries, w.generate_ms_per_chunk,
                    w.place_ms_per_chunk, w.resolve_ms_per_chunk, w.build_s);
      csv << line;
    }
  }
  return csv.str();
}

std::array<uint8_t, 3> heat_colour(double t) {
  static const double stops[5][3] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
  t = std::clamp(t, 0.0, 1.0) * 4.0;
  const int k = std::min(3, int(t));
  const double f = t - k;
  std::array<uint8_t, 3> c{};
  for (int ch = 0; ch < 3; ++ch) c[size_t(ch)] = uint8_t(std::lround(stops[k][ch] + (stops[k + 1][ch] - stops[k][ch]) * f));
  return c;
}

std::vector<uint8_t> heatmap_png(const WorldProfile& world, double max_per_ha, int zoom) {
  const int bar = 24, gap = 8;
  const int map_w = world.heat_width * zoom, h = std::max(1, world.heat_height * zoom);
  const int width = map_w + gap + bar;
  std::vector<uint8_t> rgb(size_t(width) * h * 3, 255);
  const double cell_ha = kHeatCell * kHeatCell / 1e4;
  for (int py = 0; py < h; ++py) {
    const int cy = world.heat_height - 1 - py / zoom;  // north (+y) up
    for (int px = 0; px < map_w; ++px) {
      const size_t cell = size_t(cy) * world.heat_width + px / zoom;
      std::array<uint8_t, 3> c = {40, 40, 40};
      if (world.heat_inside[cell]) c = heat_colour(max_per_ha > 0 ? world.heat[cell] / cell_ha / max_per_ha : 0);
      std::copy(c.begin(), c.end(), rgb.begin() + (size_t(py) * width + px) * 3);
    }
    const std::array<uint8_t, 3> c = heat_colour(1.0 - double(py) / std::max(1, h - 1));  // colour bar, max at top
    for (int px = map_w + gap; px < width; ++px) std::copy(c.begin(), c.end(), rgb.begin() + (size_t(py) * width + px) * 3);
  }
  return io::encode_png_rgb8(rgb, width, h);
}

}  // namespace silva::bench

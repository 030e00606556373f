#pragma once
/// @file Files of `silva profile placement`: JSON and CSV of a sweep, top-down density heatmaps.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/harness/profile_world.hpp"
#include "core/ontology.hpp"

namespace silva::bench {

/// One profiled world of the sweep and the settings that made it.
struct ProfileSample {
  double density = 0;        ///< vegetation.density (%).
  double max_elevation = 0;  ///< terrain.max_elevation (m).
  bool trail = true;         ///< trail.enabled.
  int64_t seed = 0;          ///< World seed.
  WorldProfile world;        ///< What it holds and cost.
};

/// A sample as JSON: settings, "world" {...} and "classes" {name: {...}} (classes with candidates).
nlohmann::json sample_json(const ProfileSample& s, const Ontology& ontology);

/// Means over samples of equal settings (density, max_elevation, trail), in first-seen order:
/// [{"density", "max_elevation", "trail", "seeds", "world": {...}, "classes": {...}}]; counts and
/// times are means, nearest-neighbour figures means of the per-seed figures.
nlohmann::json sweep_means(const std::vector<ProfileSample>& samples, const Ontology& ontology);

/// CSV with a header and one row per (sample, class with candidates).
std::string samples_csv(const std::vector<ProfileSample>& samples, const Ontology& ontology);

/// A top-down heatmap PNG of things per hectare (colour scale 0..max_per_ha, viridis-like; cells
/// outside the built chunks dark grey; north up), each cell `zoom` pixels, with a colour bar.
std::vector<uint8_t> heatmap_png(const WorldProfile& world, double max_per_ha, int zoom);

/// Colour of t in [0, 1] on the viridis-like scale (R, G, B).
std::array<uint8_t, 3> heat_colour(double t);

}  // namespace silva::bench

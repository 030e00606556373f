#include "core/material.hpp"

#include <cstring>

namespace silva {

namespace {
constexpr const char* kNames[int(Material::Count)] = {
    "ground", "trail", "bark_conifer", "bark_broadleaf", "bark_dead", "needles",
    "leaves", "grass", "fern", "shrub_leaves", "rock", "wood",
    "log_bark", "broken_wood", "moss", "leaf_litter",
    "bark_spruce", "bark_pine", "bark_larch", "bark_beech", "bark_birch", "bark_oak",
    "needles_spruce", "needles_pine", "needles_larch", "leaves_beech", "leaves_birch", "leaves_oak",
    "autumn_leaves", "autumn_needles", "bare_twigs", "autumn_grass", "winter_grass", "dead_bracken", "soil",
    "herb", "spring_leaves", "petals", "matted_bracken"};
}  // namespace

const char* material_name(Material m) { return kNames[int(m)]; }

bool parse_material(const char* name, Material& out) {
  for (int i = 0; i < int(Material::Count); ++i)
    if (std::strcmp(name, kNames[i]) == 0) {
      out = Material(i);
      return true;
    }
  return false;
}

}  // namespace silva

#pragma once
/// @file The trail's surface family (trail.surface): how the walked band looks in RGB. Labels never
/// depend on it (the trail's class and shape are the same for every family).
#include <array>
#include <string_view>

namespace silva {

/// One family of trail surfaces.
enum class TrailSurface : unsigned char {
  PackedEarth,  ///< Compacted light soil with embedded stones and a few roots.
  Gravel,       ///< Grey-beige gravel, densely packed small stones, a few larger ones.
  Roots,        ///< Dark eroded soil crossed by many roots, stones washed out between them.
  LeafCovered,  ///< The forest floor's litter over most of the band, soil showing along the trodden line.
  Muddy,        ///< Dark wet mud, glossy, with two ruts that hold standing water in any weather.
  GrassRuts,    ///< Two bare wheel ruts with grass between them and along the edges.
};

/// Number of trail surface families.
inline constexpr int kTrailSurfaceCount = 6;

/// The config names of the families, in enum order.
inline constexpr std::array<std::string_view, kTrailSurfaceCount> kTrailSurfaceNames = {
    "packed_earth", "gravel", "roots", "leaf_covered", "muddy", "grass_ruts"};

/// The config name of a family.
std::string_view trail_surface_name(TrailSurface s);

/// Parses a family name; false when unknown ("random" is not a family).
bool parse_trail_surface(std::string_view name, TrailSurface& out);

}  // namespace silva

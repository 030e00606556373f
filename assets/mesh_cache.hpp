#pragma once
/// @file The mesh cache: a procedural variant's LOD meshes, once generated and simplified, kept on
/// disk so that later runs of the same executable load them instead of building them again (LOD
/// building is most of a short run's fixed cost). Entries are keyed by the executable's GNU build
/// id as well as the variant, so a rebuilt generator never reads another build's meshes; a missing,
/// unreadable or damaged entry is rebuilt, and a cache that cannot be written is skipped.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/mesh.hpp"
#include "core/season.hpp"

namespace silva::assets {

struct ProceduralSource;

/// The cache's root: `silva_mesh_cache` ($SILVA_MESH_CACHE) when set and not "off", else
/// `xdg_cache_home`/silva/meshes, else `home`/.cache/silva/meshes; empty when off or nothing is set.
std::filesystem::path mesh_cache_root(const char* silva_mesh_cache, const char* xdg_cache_home, const char* home);

/// This executable's GNU build id in hex, or "" when it has none.
std::string executable_build_id();

/// This process's cache folder: mesh_cache_root from the environment / "build-" executable_build_id(),
/// or empty (no cache) when either is missing. Resolved once.
const std::filesystem::path& process_mesh_cache();

/// True when process_mesh_cache() already holds masks (so the meshes drawn are likely read, not generated).
bool process_mesh_cache_warm();

/// The variant's LOD meshes: read from `folder` when it holds an intact entry for `source` and
/// `season`, else made by `make` and stored there (atomically; failures to store are ignored). An
/// empty `folder` just calls `make`.
std::vector<Mesh> cached_lods(const std::filesystem::path& folder, const ProceduralSource& source, Season season,
                              const std::function<std::vector<Mesh>()>& make);

}  // namespace silva::assets

// `silva assets build` after the CLI checks.

#include "app/commands/assets/asset_files.hpp"
#include "app/commands/assets/assets_command.hpp"

namespace silva::app {

int run_assets_build(const AssetsBuildRequest& request, const Reporter& reporter) {
  const std::filesystem::path dir = request.out_dir.empty() ? std::filesystem::path(SILVA_ASSET_DIR) : request.out_dir;
  const assets::AssetLibrary library = build_library(dir, request.glb, assets::kDefaultAssetSeed, request.max_variants);
  reporter.result({{"ok", true}, {"dir", dir.string()}, {"assets", library.assets.size()}},
                  "wrote " + std::to_string(library.assets.size()) + " assets and library.json to " + dir.string());
  return 0;
}

}  // namespace silva::app

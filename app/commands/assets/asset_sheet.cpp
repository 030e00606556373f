#include "app/commands/assets/asset_sheet.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "app/commands/assets/assets_command.hpp"
#include "core/camera.hpp"
#include "io/atomic_file.hpp"
#include "io/png_writer.hpp"
#include "io/label_images.hpp"
#include "render/lighting.hpp"
#include "render/renderer.hpp"
#include "render/shade.hpp"
#include "systems/write_dataset.hpp"

namespace silva::app {

namespace {

/// Half side of the square ground plane under each asset (m) and its grid cells per side.
constexpr float kGroundHalf = 60.0f;
constexpr int kGroundCells = 48;

/// A flat forest-floor square centred on the origin, in a kGroundCells grid (so it shades and
/// shadows like terrain).
Mesh ground_plane() {
  Mesh m;
  const int n = kGroundCells;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float x = -kGroundHalf + 2.0f * kGroundHalf * float(i) / float(n);
      const float y = -kGroundHalf + 2.0f * kGroundHalf * float(j) / float(n);
      m.positions.emplace_back(x, y, 0.0f);
      m.normals.emplace_back(Vec3f::UnitZ());
      m.uvs.emplace_back(-1.0f, -1.0f);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1), d = c + 1;
      m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
    }
  MeshPart part;
  part.index_count = uint32_t(m.indices.size());
  m.parts.push_back(part);
  return m;
}

/// A camera looking at `bounds` from the south-west, far enough that the bounds fill the view:
/// low for tall assets, steeper for small ones.
Camera framing_camera(const AABB& bounds, int size) {
  constexpr double kFov = 40.0;
  const Vec3d lo = bounds.min.cast<double>(), hi = bounds.max.cast<double>();
  const Vec3d centre = 0.5 * (lo + hi);
  const double radius = std::max(0.5 * (hi - lo).norm(), 0.2);
  const double pitch = (hi.z() - lo.z()) > 3.0 ? -8.0 : -30.0;
  const double yaw = 35.0;
  const double dist = 1.08 * radius / std::tan(0.5 * kFov * std::numbers::pi / 180.0);
  const double p = pitch * std::numbers::pi / 180.0, y = yaw * std::numbers::pi / 180.0;
  const Vec3d forward(std::cos(p) * std::cos(y), std::cos(p) * std::sin(y), std::sin(p));
  Camera cam = Camera::from_fov(size, size, kFov, 0.05, 1000.0);
  cam.camera_to_world = pose_from_angles(centre - dist * forward, yaw, pitch, 0.0);
  return cam;
}

/// Renders `asset` on the ground plane: RGB and semantic colour views of `size` x `size`.
void render_cell(const assets::Asset& asset, const Mesh& ground, int size, std::vector<uint8_t>& rgb,
                 std::vector<uint8_t>& semantic) {
  render::Scene scene;
  scene.meshes.emplace_back().lods = {&ground};
  render::MeshLods lods;
  for (const Mesh& m : asset.lods()) lods.lods.push_back(&m);
  if (const Mesh& caster = asset.geometry->shadow_caster(); &caster != &asset.lods()[0]) lods.shadow_caster = &caster;
  lods.lod_screen_sizes = asset.lod_screen_sizes;
  scene.meshes.push_back(lods);
  for (auto& m : scene.meshes) m.compute_bounds();
  scene.instances.push_back({Affine3f::Identity(), 0, 0, 1});
  scene.instances.push_back({Affine3f::Identity(), 1, role_has_instances(asset.role) ? 1u : 0u, 7});

  const Camera camera = framing_camera(asset.lods()[0].bounds(), size);
  const render::LightingPreset preset = render::builtin_presets().at("day");
  render::Renderer renderer;
  render::GBuffer gbuffer;
  const render::RenderOptions options;
  renderer.render_gbuffer(scene, camera, options, gbuffer);
  const AABB region{Vec3f(-kGroundHalf, -kGroundHalf, -1.0f), Vec3f(kGroundHalf, kGroundHalf, 40.0f)};
  const render::ShadowMap shadow =
      renderer.render_shadow_map(scene, render::sun_direction(preset).cast<double>(), region, 2048, options);
  render::shade_rgb({gbuffer, camera, preset, &shadow, 1, "sheet", 0, {}}, rgb);
  semantic = io::semantic_color_image(systems::label_planes(gbuffer), default_ontology());
}

/// Copies a size x size RGB8 view into `sheet` (width `sheet_w`) at pixel (x0, y0).
void blit(const std::vector<uint8_t>& view, int size, std::vector<uint8_t>& sheet, int sheet_w, int x0, int y0) {
  for (int v = 0; v < size; ++v)
    std::copy_n(view.begin() + ptrdiff_t(v) * size * 3, size_t(size) * 3,
                sheet.begin() + (ptrdiff_t(y0 + v) * sheet_w + x0) * 3);
}

}  // namespace

std::vector<const assets::Factory*> select_factories(const std::string& names) {
  std::vector<const assets::Factory*> out;
  size_t start = 0;
  while (start <= names.size()) {
    const size_t comma = std::min(names.find(',', start), names.size());
    const std::string name = names.substr(start, comma - start);
    size_t matched = 0;
    for (const assets::Factory& f : assets::factories())
      if (name == assets::kind_name(f.kind) || name == f.prefix) {
        ++matched;
        if (std::find(out.begin(), out.end(), &f) == out.end()) out.push_back(&f);
      }
    if (matched == 0) return {};
    start = comma + 1;
  }
  return out;
}

std::vector<uint8_t> render_asset_sheet(const std::vector<const assets::Factory*>& factories, int count, uint64_t seed,
                                        const SheetLayout& layout, int& width, int& height) {
  std::vector<assets::Asset> assets;
  for (const assets::Factory* f : factories)
    for (uint32_t v = 0; v < std::min<uint32_t>(uint32_t(count), f->variants); ++v)
      assets.push_back(assets::make_asset(*f, seed, v));
  const int cols = std::min<int>(layout.columns, int(assets.size()));
  const int rows = (int(assets.size()) + cols - 1) / cols;
  width = cols * 2 * layout.cell;
  height = rows * layout.cell;
  std::vector<uint8_t> sheet(size_t(width) * size_t(height) * 3, 0);
  const Mesh ground = ground_plane();
  std::vector<uint8_t> rgb, semantic;
  for (size_t i = 0; i < assets.size(); ++i) {
    render_cell(assets[i], ground, layout.cell, rgb, semantic);
    const int x0 = int(i % size_t(cols)) * 2 * layout.cell, y0 = int(i / size_t(cols)) * layout.cell;
    blit(rgb, layout.cell, sheet, width, x0, y0);
    blit(semantic, layout.cell, sheet, width, x0 + layout.cell, y0);
  }
  return sheet;
}

int run_assets_sheet(const AssetsSheetRequest& request, const Reporter& reporter) {
  const std::vector<const assets::Factory*> factories = select_factories(request.kind);
  int width = 0, height = 0;
  const std::vector<uint8_t> sheet =
      render_asset_sheet(factories, request.count, request.seed, {request.cell, request.columns}, width, height);
  io::write_file_atomic(request.out, io::encode_png_rgb8(sheet, width, height));
  std::string names;
  for (const assets::Factory* f : factories) names += std::string(names.empty() ? "" : ", ") + f->prefix;
  reporter.result({{"ok", true}, {"file", request.out.string()}, {"width", width}, {"height", height}},
                  "wrote " + request.out.string() + " (" + std::to_string(width) + "x" + std::to_string(height) +
                      ": " + names + "; RGB left, semantic right, variants 0.." +
                      std::to_string(request.count - 1) + " row by row)");
  return 0;
}

}  // namespace silva::app

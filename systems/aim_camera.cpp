#include "systems/aim_camera.hpp"

#include <algorithm>

#include "components/camera.hpp"
#include "components/chunk.hpp"
#include "components/phase.hpp"
#include "components/world_source.hpp"
#include "render/shadow_plan.hpp"
#include "systems/render_views.hpp"
#include "world/chunk_regions.hpp"
#include "world/plan_captures.hpp"
#include "world/view_fan.hpp"
#include "world/world_context.hpp"

namespace silva::systems {

/// Radius around the camera whose objects may cast shadows into its view (metres).
constexpr double kShadowCasterReach = 0.25 * render::kShadowExtent;

std::vector<ChunkCoord> capture_chunks(const Camera& camera, double chunk_size, double lidar_reach) {
  return world::chunks_for_view(camera, chunk_size, std::max(kShadowCasterReach, lidar_reach));
}

ViewChunks frame_chunks(const world::PlannedFrame& f, double chunk_size, double lidar_reach) {
  ViewChunks view;
  view.coords = capture_chunks(f.camera, chunk_size, lidar_reach);
  if (f.fan_yaws_deg.empty()) return view;
  for (const Camera& c : world::view_fan(f)) {
    const std::vector<ChunkCoord> more = capture_chunks(c, chunk_size, lidar_reach);
    view.fan.insert(view.fan.end(), more.begin(), more.end());
  }
  // The frame's own chunks too: its rebuilt view (view_fan) may round differently at a chunk border.
  view.fan.insert(view.fan.end(), view.coords.begin(), view.coords.end());
  std::sort(view.fan.begin(), view.fan.end());
  view.fan.erase(std::unique(view.fan.begin(), view.fan.end()), view.fan.end());
  return view;
}

double lidar_reach(const CaptureSettings& settings) {
  return settings.outputs.has(io::OutputType::Lidar) ? settings.lidar.max_range : 0.0;
}

void install_aim_camera(ecs::World& world) {
  world.set_resource(CaptureQueue{});
  world.set_resource(ViewChunks{});
  world.system("aim_camera")
      .phase(Phase::Stream)
      .reads_resource<WorldSource, CaptureSettings>()
      .writes_resource<CaptureQueue, ViewChunks>()
      .reads<world::PlannedFrame>()
      .run([](ecs::SystemContext& sys) {
        CaptureQueue& queue = sys.resource<CaptureQueue>();
        ViewChunks& view = sys.resource<ViewChunks>();
        view = ViewChunks{};
        queue.active = queue.pending() ? queue.cameras[queue.next++] : ecs::null_entity;
        if (queue.active.is_null()) return;
        const double chunk_size = sys.resource<const WorldSource>().ctx->chunk_size();
        // A LiDAR sees all around: the disc out to its range, when it is selected.
        view = frame_chunks(sys.get<const world::PlannedFrame>(queue.active), chunk_size,
                            lidar_reach(sys.resource<const CaptureSettings>()));
      });
}

}  // namespace silva::systems

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
#include "world/world_context.hpp"

namespace silva::systems {

/// Radius around the camera whose objects may cast shadows into its view (metres).
constexpr double kShadowCasterReach = 0.25 * render::kShadowExtent;

std::vector<ChunkCoord> capture_chunks(const Camera& camera, double chunk_size, double lidar_reach) {
  return world::chunks_for_view(camera, chunk_size, std::max(kShadowCasterReach, lidar_reach));
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
        view.coords.clear();
        queue.active = queue.pending() ? queue.cameras[queue.next++] : ecs::null_entity;
        if (queue.active.is_null()) return;
        const double chunk_size = sys.resource<const WorldSource>().ctx->chunk_size();
        const Camera& camera = sys.get<const world::PlannedFrame>(queue.active).camera;
        // A LiDAR sees all around: the disc out to its range, when it is selected.
        view.coords = capture_chunks(camera, chunk_size, lidar_reach(sys.resource<const CaptureSettings>()));
      });
}

}  // namespace silva::systems

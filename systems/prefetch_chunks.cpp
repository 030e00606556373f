#include "systems/prefetch_chunks.hpp"

#include <utility>

#include "components/camera.hpp"
#include "components/phase.hpp"
#include "components/world_source.hpp"
#include "systems/aim_camera.hpp"
#include "systems/render_views.hpp"
#include "world/chunk_cache.hpp"
#include "world/plan_captures.hpp"

namespace silva::systems {

PrefetchedChunks::~PrefetchedChunks() { drop_batch(); }

void PrefetchedChunks::drop_batch() {
  if (!batch_) return;
  try {
    batch_->work.wait();
  } catch (...) {  // NOLINT(bugprone-empty-catch): dropped chunks; the Stream phase makes its own and reports
  }
  batch_.reset();
}

void PrefetchedChunks::start(const world::WorldContext& ctx, std::vector<ChunkCoord> coords) {
  drop_batch();
  batch_ = std::make_unique<Batch>();
  Batch& b = *batch_;
  b.coords = std::move(coords);
  b.work.run([&b, &ctx] { b.contents = world::drawable_chunks(ctx, b.coords); });
}

std::vector<std::shared_ptr<ChunkContent>> PrefetchedChunks::take(const std::vector<ChunkCoord>& wanted) {
  if (!batch_) return {};
  const std::unique_ptr<Batch> b = std::move(batch_);
  b->work.wait();
  if (wanted.empty() || wanted != b->coords) return {};
  return std::move(b->contents);
}

const std::vector<ChunkCoord>& PrefetchedChunks::started() const {
  static const std::vector<ChunkCoord> none;
  return batch_ ? batch_->coords : none;
}

namespace {
/// True when `f` is another frame of `active`'s view fan (same position, same fan).
bool same_fan(const world::PlannedFrame& f, const world::PlannedFrame& active) {
  return !f.fan_yaws_deg.empty() && f.fan_yaws_deg == active.fan_yaws_deg &&
         f.camera.position() == active.camera.position();
}
}  // namespace

void install_prefetch_chunks(ecs::World& world) {
  if (!world.has_resource<PrefetchedChunks>()) world.set_resource(PrefetchedChunks{});
  world.system("prefetch_chunks")
      .phase(Phase::Prepare)
      .after("prepare_scene")
      .reads_resource<WorldSource, CaptureQueue, CaptureSettings, world::ChunkCache>()
      .writes_resource<PrefetchedChunks>()
      .reads<world::PlannedFrame>()
      .run([](ecs::SystemContext& sys) {
        const CaptureQueue& queue = sys.resource<const CaptureQueue>();
        PrefetchedChunks& prefetched = sys.resource<PrefetchedChunks>();
        if (queue.active.is_null() || !queue.pending() || !prefetched.started().empty()) return;
        const world::WorldContext& ctx = *sys.resource<const WorldSource>().ctx;
        const world::PlannedFrame& active = sys.get<const world::PlannedFrame>(queue.active);
        size_t k = queue.next;  // past the rest of the active frame's fan: those stream nothing new
        while (k + 1 < queue.cameras.size() && same_fan(sys.get<const world::PlannedFrame>(queue.cameras[k]), active)) ++k;
        std::vector<ChunkCoord> missing = sys.resource<const world::ChunkCache>().missing(
            frame_chunks(sys.get<const world::PlannedFrame>(queue.cameras[k]), ctx.chunk_size(),
                         lidar_reach(sys.resource<const CaptureSettings>()))
                .streamed());
        if (!missing.empty()) prefetched.start(ctx, std::move(missing));
      });
}

}  // namespace silva::systems

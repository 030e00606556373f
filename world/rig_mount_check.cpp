#include "world/rig_mount_check.hpp"

#include <cstdio>
#include <string>

#include "core/error.hpp"
#include "core/rig_presets.hpp"
#include "world/parallel_plan.hpp"
#include "world/pose_clearance.hpp"
#include "world/stereo_rig.hpp"

namespace silva::world {

namespace {

/// The keys that place the rig's cameras, e.g. `rig.preset = "stereo", rig.cameras = 2, rig.baseline_m = 2`
/// (rig.height_m when set).
std::string rig_keys(const RigConfig& rig) {
  char text[160];
  std::snprintf(text, sizeof text, "rig.preset = \"%s\", rig.cameras = %d, rig.baseline_m = %g", rig.preset.c_str(),
                rig.cameras, rig.baseline_m);
  std::string keys = text;
  if (rig.height_m > 0) {
    std::snprintf(text, sizeof text, ", rig.height_m = %g", rig.height_m);
    keys += text;
  }
  return keys;
}

/// Throws when `camera` (named `which`) of frame `f` is inside a solid object near it.
void check_camera(const WorldContext& ctx, ChunkSource& chunks, const CrownProfiles& crowns, const PlannedFrame& f,
                  const Camera& camera, const char* which) {
  const Vec3d p = camera.position();
  const ClearanceProbe probe = ClearanceProbe::around(ctx, chunks, crowns, p.x(), p.y(), 0.0);
  const Vegetation* inside = probe.solid_at(p, ctx.config.camera.near);
  if (!inside) return;
  char where[160];
  std::snprintf(where, sizeof where, "%s frame %d at (%.2f, %.2f, %.2f)", f.sequence.c_str(), f.frame, p.x(), p.y(),
                p.z());
  throw InputError(rig_keys(ctx.config.rig) + ": the " + which + " camera of " + where + " is inside a " +
                   assets::kind_name(ctx.library->assets[inside->asset].kind) +
                   " (its collision proxy); choose a smaller rig.baseline_m, another rig.height_m or other poses");
}

}  // namespace

void check_rig_mounts(const WorldContext& ctx, ChunkCache& cache, const std::vector<PlannedFrame>& frames) {
  const RigConfig& rig = ctx.config.rig;
  if (rig.cameras == 1 && rig.height_m == 0) return;
  const CrownProfiles crowns(*ctx.library);
  const double baseline = stereo_baseline_m(rig);
  plan_in_parallel(cache, frames.size(), [&](size_t i, ChunkSource& chunks) {
    const PlannedFrame& f = frames[i];
    if (f.walk) check_camera(ctx, chunks, crowns, f, f.camera, "left");
    if (baseline > 0) check_camera(ctx, chunks, crowns, f, stereo_right(f, baseline).camera, "right");
  });
}

}  // namespace silva::world

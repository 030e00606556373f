#include "render/camera_optics.hpp"

#include <utility>

#include "render/chromatic_aberration.hpp"
#include "render/depth_of_field.hpp"
#include "render/motion_blur.hpp"

namespace silva::render {

bool needs_whole_frame(const CameraModel& model) {
  return model.motion || model.depth_of_field || model.chromatic_aberration > 0.0;
}

void apply_optics(LinearFrame& frame, LinearFrame& scratch, const std::vector<float>& depth, const Camera& camera,
                  const CameraModel& model) {
  if (model.motion) {
    apply_motion_blur(frame, depth, camera, *model.motion, scratch);
    std::swap(frame, scratch);
  }
  if (model.depth_of_field) {
    apply_depth_of_field(frame, depth, camera, *model.depth_of_field, scratch);
    std::swap(frame, scratch);
  }
  if (model.chromatic_aberration > 0.0) {
    apply_chromatic_aberration(frame, camera, float(model.chromatic_aberration), scratch);
    std::swap(frame, scratch);
  }
}

}  // namespace silva::render

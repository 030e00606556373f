#pragma once
/// @file The camera/sensor model applied to RGB only (CONTRACT.md "Camera model"): shot + read
/// sensor noise, vignetting, lateral chromatic aberration, thin-lens depth of field and motion
/// blur, sky glare. Plain data shared by the renderer (render/) and the camera file (io/).
#include <optional>

#include "core/camera.hpp"
#include "core/config.hpp"
#include "core/types.hpp"

namespace silva {

/// Shot + read noise on the linear signal: e = clamp(x, 0, 1) * full_well_e / gain electrons,
/// std-dev sqrt(e + read_noise_e^2) electrons.
struct SensorNoise {
  double full_well_e = 10000;  ///< Electrons at full scale at gain 1.
  double read_noise_e = 3;     ///< Read noise std-dev, electrons.
  double gain = 2;             ///< Analog gain: full scale is full_well_e / gain electrons.
  double max_gain = 32;        ///< The auto gain's ceiling (exposed_camera_model).
  double aperture_ev = 8.643856189774724;  ///< log2(f_number^2 / shutter_s) (f/2, 1/100 s): the darkest EV100 gain 1 exposes.
  bool operator==(const SensorNoise&) const = default;
};

/// Colour lost per stop of gain above the base gain: the chroma noise reduction of a camera at high
/// gain keeps 1 / (1 + kChromaLossPerStop x stops) of each pixel's colour.
inline constexpr double kChromaLossPerStop = 0.4;

/// Thin-lens depth of field, focused at `focus_distance` metres along the optical axis.
struct DepthOfField {
  double f_number = 2;          ///< Aperture f-number N.
  double focus_distance = 3;    ///< Distance in focus, metres along the optical axis.
  double focal_length_mm = 5.65;  ///< Focal length: sensor width * fx / image width.
  bool operator==(const DepthOfField&) const = default;
};

/// The camera's motion during the exposure; the frame's own pose is the middle of it.
struct ExposureMotion {
  double shutter_s = 0.01;                  ///< Exposure time, seconds.
  Mat4d open_to_world = Mat4d::Identity();   ///< Camera-to-world when the shutter opens.
  Mat4d close_to_world = Mat4d::Identity();  ///< Camera-to-world when the shutter closes.
  bool operator==(const ExposureMotion&) const = default;
};

/// What the camera does to the RGB image (labels, depth and normals never see it).
struct CameraModel {
  std::optional<SensorNoise> noise;            ///< Sensor noise, or none.
  double vignetting = 0;                       ///< Strength of the cos^4 falloff, 0 = none, 1 = the full law.
  double chromatic_aberration = 0;             ///< Lateral CA: R sampled at radius (1 - k), B at (1 + k).
  double bloom = 0;                            ///< Share of the sky's light spread over the glare halo (render/sky_glare.hpp).
  std::optional<DepthOfField> depth_of_field;  ///< Thin-lens blur, or a pinhole.
  std::optional<ExposureMotion> motion;        ///< Camera motion during the exposure, or a still camera.
  double chroma = 1;                           ///< Share of each pixel's colour kept (1 = all; exposed_camera_model).
  int jpeg_quality = 0;                        ///< JPEG quality of the camera's stream (0 = none), applied last.
  bool operator==(const CameraModel&) const = default;
};

/// `model` exposed for a scene of `ev100`: the sensor's gain raised to what the exposure needs,
/// 2^(aperture_ev - ev100), between its base gain and max_gain (dark scenes get noisier), and the colour
/// the camera keeps at that gain (chroma, kChromaLossPerStop per stop above the base gain).
CameraModel exposed_camera_model(const CameraModel& model, double ev100);

/// The model `[camera]` configures for `camera`'s image (its focal length in pixels gives the
/// lens's in millimetres); `motion` is left empty, as it belongs to each frame.
CameraModel camera_model(const CameraConfig& config, const Camera& camera);

}  // namespace silva

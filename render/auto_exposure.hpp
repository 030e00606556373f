#pragma once
/// @file Auto-exposure: the EV100 that exposes a frame's log-average luminance to mid-grey.
#include "render/linear_frame.hpp"

namespace silva::render {

/// Tone-curve input the log-average luminance of an auto-exposed frame is mapped to: set so that the
/// day preset's forest views meter on average at its own ev100 14.5 (a forest is darker than mid-grey).
inline constexpr float kAutoExposureKey = 0.067f;
/// Pixel spacing of the metering grid: pixel (kMeterStep i + kMeterStep / 2, kMeterStep j + kMeterStep / 2).
inline constexpr int kMeterStep = 4;
/// Luminance floor of the metering (kcd/m², about a starless overcast night), so a black pixel
/// does not send the log-average to zero.
inline constexpr double kMeterFloor = 1e-7;
/// The metered EV100 is kept within the preset field's range.
inline constexpr float kMinEv100 = -10.0f, kMaxEv100 = 20.0f;

/// Log-average Rec.709 luminance of `frame` (kcd/m²) over the metering grid: exp of the mean of
/// log(max(L, kMeterFloor)), summed per grid row in parallel and over rows in order (the value
/// never depends on threads).
double log_average_luminance(const LinearFrame& frame);

/// The EV100 whose exposure_multiplier maps luminance `luminance` (kcd/m²) to kAutoExposureKey:
/// log2(luminance · 2000 / (1.2 · key)), clamped to [kMinEv100, kMaxEv100].
float ev100_for_luminance(double luminance);

}  // namespace silva::render

#include "render/auto_exposure.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/det_math.hpp"

namespace silva::render {

double log_average_luminance(const LinearFrame& frame) {
  const int rows = (frame.height + kMeterStep - 1 - kMeterStep / 2) / kMeterStep;
  const int cols = (frame.width + kMeterStep - 1 - kMeterStep / 2) / kMeterStep;
  if (rows <= 0 || cols <= 0) return kMeterFloor;
  std::vector<double> row_sums(size_t(rows), 0.0);
  tbb::parallel_for(tbb::blocked_range<int>(0, rows), [&](const tbb::blocked_range<int>& range) {
    for (int j = range.begin(); j < range.end(); ++j) {
      const Vec3f* row = &frame.rgb[size_t(kMeterStep * j + kMeterStep / 2) * size_t(frame.width)];
      double sum = 0;
      for (int i = 0; i < cols; ++i) {
        const Vec3f& c = row[kMeterStep * i + kMeterStep / 2];
        const double y = 0.2126 * double(c.x()) + 0.7152 * double(c.y()) + 0.0722 * double(c.z());
        sum += det_log(std::max(y, kMeterFloor));
      }
      row_sums[size_t(j)] = sum;
    }
  });
  double total = 0;
  for (const double s : row_sums) total += s;
  return det_exp(total / (double(rows) * double(cols)));
}

float ev100_for_luminance(double luminance) {
  // exposure_multiplier(ev) = 2000 / 1.2 · 2^-ev; solve luminance · multiplier = key for ev.
  const double ev = std::log2(std::max(luminance, kMeterFloor) * 2000.0 / (1.2 * double(kAutoExposureKey)));
  return std::clamp(float(ev), kMinEv100, kMaxEv100);
}

}  // namespace silva::render

#include "core/noise.hpp"

#include <cmath>
#include <cstdint>

namespace silva {

namespace {

/// Ken Perlin's reference permutation of 0..255.
constexpr uint8_t kPerm[256] = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103, 30,  69,  142,
    8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,  197, 62,  94,  252, 219, 203,
    117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174, 20,  125, 136, 171, 168, 68,  175, 74,  165,
    71,  134, 139, 48,  27,  166, 77,  146, 158, 231, 83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,
    55,  46,  245, 40,  244, 102, 143, 54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,
    18,  169, 200, 196, 135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250,
    124, 123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,  182, 189,
    28,  42,  223, 183, 170, 213, 119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101, 155, 167, 43,  172, 9,
    129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185, 112, 104, 218, 246, 97,  228, 251, 34,
    242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,  51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,
    181, 199, 106, 157, 184, 84,  204, 176, 115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,  222, 114,
    67,  29,  24,  72,  243, 141, 128, 195, 78,  66,  215, 61,  156, 180};

/// The 12 gradient directions of Gustavson's simplex noise (x, y components).
constexpr double kGrad[12][2] = {{1, 1}, {-1, 1}, {1, -1}, {-1, -1}, {1, 0}, {-1, 0},
                                 {1, 0}, {-1, 0}, {0, 1},  {0, -1}, {0, 1}, {0, -1}};

/// Permutation lookup with wrap.
inline int perm(int i) { return kPerm[i & 255]; }

/// Contribution of one simplex corner at offset (x, y) with gradient index gi.
inline double corner(double x, double y, int gi) {
  double t = 0.5 - x * x - y * y;
  if (t < 0) return 0.0;
  t = t * t;
  return t * t * (kGrad[gi][0] * x + kGrad[gi][1] * y);
}

}  // namespace

SimplexTables simplex2_tables() { return {kPerm, kGrad}; }

double simplex2(double xin, double yin) {
  const double F2 = 0.5 * (std::sqrt(3.0) - 1.0);
  const double G2 = (3.0 - std::sqrt(3.0)) / 6.0;
  const double s = (xin + yin) * F2;
  const double fi = std::floor(xin + s);
  const double fj = std::floor(yin + s);
  const double t = (fi + fj) * G2;
  const double x0 = xin - (fi - t);
  const double y0 = yin - (fj - t);
  const int i1 = x0 > y0 ? 1 : 0;
  const int j1 = 1 - i1;
  const double x1 = x0 - i1 + G2;
  const double y1 = y0 - j1 + G2;
  const double x2 = x0 - 1.0 + 2.0 * G2;
  const double y2 = y0 - 1.0 + 2.0 * G2;
  // Lattice coordinates wrap at 256 (the permutation period).
  const int ii = int(int64_t(fi) & 255);
  const int jj = int(int64_t(fj) & 255);
  const int g0 = perm(ii + perm(jj)) % 12;
  const int g1 = perm(ii + i1 + perm(jj + j1)) % 12;
  const int g2 = perm(ii + 1 + perm(jj + 1)) % 12;
  return 70.0 * (corner(x0, y0, g0) + corner(x1, y1, g1) + corner(x2, y2, g2));
}

double fbm2(const FbmParams& p, double x, double y) {
  double sum = 0.0, amp_sum = 0.0, amp = 1.0, freq = p.frequency;
  for (int o = 0; o < p.octaves; ++o) {
    // A fixed per-octave shift decorrelates the octaves at the offset point.
    const double shift = 31.7 * o;
    sum += amp * simplex2(x * freq + (p.offset_x + shift), y * freq + (p.offset_y + shift));
    amp_sum += amp;
    amp *= p.persistence;
    freq *= p.lacunarity;
  }
  return amp_sum > 0.0 ? sum / amp_sum : 0.0;
}

}  // namespace silva

#pragma once
/// @file Rounding, exp and log built only from +, -, *, / and exact scaling by powers of two, so shading
/// gives the same bits on every CPU (libm's exp/log may pick FMA code paths at run time).
#include <bit>
#include <cmath>
#include <cstdint>

namespace silva {

/// std::llround without the libm call (hot in triangle setup): nearest integer, halves away from
/// zero, for |x| < 2^52 (x - trunc(x) is then exact).
inline int64_t round_half_away(double x) {
  int64_t i = int64_t(x);  // truncates toward zero
  const double frac = x - double(i);
  if (frac >= 0.5) ++i;
  if (frac <= -0.5) --i;
  return i;
}

/// 1/n! for n = 0..13, evaluated at compile time (correctly rounded divisions).
inline constexpr auto kInverseFactorials = [] {
  struct Table {
    double v[14];
  } t{};
  double f = 1.0;
  for (int n = 0; n < 14; ++n) {
    if (n > 0) f *= double(n);
    t.v[n] = 1.0 / f;
  }
  return t;
}();

/// e^x for |x| <= 700: x = k ln2 + r with |r| <= ln2/2, e^r by its degree-13 Taylor polynomial
/// in Horner form (relative error below 1e-15), then scaled exactly by 2^k (exponent bits).
inline double det_exp(double x) {
  constexpr double kLn2Hi = 0.693147180369123816490, kLn2Lo = 1.90821492927058770002e-10;
  constexpr double kInvLn2 = 1.44269504088896338700;
  if (x > 700.0) x = 700.0;
  if (x < -700.0) return 0.0;
  // Round to nearest even by the 1.5 * 2^52 trick: the same value as std::nearbyint in the
  // default rounding mode for |x kInvLn2| < 2^51, without a libm call.
  constexpr double kRound = 6755399441055744.0;
  const double k = (x * kInvLn2 + kRound) - kRound;
  const double r = (x - k * kLn2Hi) - k * kLn2Lo;
  double p = kInverseFactorials.v[13];
  for (int n = 12; n >= 0; --n) p = p * r + kInverseFactorials.v[n];
  const uint64_t bits = uint64_t(int64_t(k) + 1023) << 52;  // 2^k, k in [-1010, 1010]
  return p * std::bit_cast<double>(bits);
}

/// e^x in float for per-pixel use: x = k ln2 + r, |r| <= ln2/2, e^r by its degree-7 Taylor
/// polynomial (relative error below 3e-7), scaled exactly by 2^k; 0 below -87, clamped above 88.
inline float det_expf(float x) {
  constexpr float kLn2Hi = 0.693145751953125f, kLn2Lo = 1.428606765330187e-06f;  // hi has 16 bits: k*hi exact
  constexpr float kInvLn2 = 1.44269504088896341f;
  if (x > 88.0f) x = 88.0f;
  if (x < -87.0f) return 0.0f;
  constexpr float kRound = 12582912.0f;  // 1.5 * 2^23: round to nearest even
  const float k = (x * kInvLn2 + kRound) - kRound;
  const float r = (x - k * kLn2Hi) - k * kLn2Lo;
  float p = float(kInverseFactorials.v[7]);
  for (int n = 6; n >= 0; --n) p = p * r + float(kInverseFactorials.v[n]);
  const uint32_t bits = uint32_t(int32_t(k) + 127) << 23;  // 2^k, k in [-126, 127]
  return p * std::bit_cast<float>(bits);
}

/// Natural log of x > 0: x = m 2^e with m in [sqrt(1/2), sqrt(2)), log m = 2 atanh((m-1)/(m+1))
/// by its odd series (relative error below 1e-15), plus e ln2.
inline double det_log(double x) {
  int e = 0;
  double m = std::frexp(x, &e);  // m in [0.5, 1)
  if (m < 0.70710678118654752440) {
    m *= 2.0;
    e -= 1;
  }
  const double s = (m - 1.0) / (m + 1.0), s2 = s * s;
  double power = s, sum = 0.0;
  for (int n = 1; n <= 29; n += 2) {
    sum += power / double(n);
    power *= s2;
  }
  return 2.0 * sum + double(e) * 0.693147180559945309417;
}

}  // namespace silva

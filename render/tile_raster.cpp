// The per-target kernel is compiled once per Highway target (foreach_target) and chosen at
// run time. Every output-affecting operation is exact or correctly rounded (integer-valued
// double adds/muls for edges, separate mul and add for depth), so all targets agree bit for bit.
#include "render/tile_raster.hpp"

#include <algorithm>
#include <bit>
#include <limits>

#include "render/raster_conventions.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/tile_raster.cpp"
#include "hwy/cache_control.h"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace silva::render::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

/// Triangles of a tile fetched ahead of the one being rasterised.
constexpr size_t kPrefetchDistance = 8;

/// Lanes of doubles, at most one 8-pixel block row.
using DTag = hn::CappedTag<double, kDepthBlockSize>;

/// Minimum of the stored depths of one whole 8x8 block. Pixels of the scratch outside the tile
/// extent keep the clear depth, which only makes the minimum more conservative.
double block_minimum(const TileScratch& s, const TileJob& job, int bx, int by) {
  const DTag d;
  const double* row = s.depth.data() + size_t(by * kDepthBlockSize) * size_t(job.stride) + size_t(bx * kDepthBlockSize);
  auto m = hn::Set(d, std::numeric_limits<double>::infinity());
  for (int y = 0; y < kDepthBlockSize; ++y, row += job.stride)
    for (size_t x = 0; x < size_t(kDepthBlockSize); x += hn::Lanes(d)) m = hn::Min(m, hn::LoadU(d, row + x));
  return hn::GetLane(hn::MinOfLanes(d, m));
}

/// Resolves lanes with a depth tie one by one (lower key wins); returns the writes made.
uint64_t write_lanes_scalar(const RasterTri& t, const double* dv, const uint8_t* win_bits, const uint8_t* tie_bits,
                            size_t lanes, double* dp, uint64_t* kp) {
  uint64_t writes = 0;
  for (size_t k = 0; k < lanes; ++k) {
    const bool win = (win_bits[k / 8] >> (k % 8)) & 1;
    const bool tie = (tie_bits[k / 8] >> (k % 8)) & 1;
    if (!(win || (tie && t.key < kp[k]))) continue;
    dp[k] = dv[k];
    kp[k] = t.key;
    ++writes;
  }
  return writes;
}

/// Values (c + b*y) + a*x of a plane on lanes of image x coordinates vx at row y: the operation
/// order of PixelPlane::at and EdgeFunction::at, so lanes and scalar code agree bit for bit.
template <class D, class V>
V plane_lanes(D d, double c, double b, double a, double y, V vx) {
  return hn::Add(hn::Set(d, c + b * y), hn::Mul(hn::Set(d, a), vx));
}

/// Reverse depth of the triangle on the lanes of row py at image x coordinates vx.
template <class D, class V>
V depth_lanes(D d, const RasterTri& t, V vx, double py) {
  return plane_lanes(d, t.depth.c, t.depth.b, t.depth.a, py, vx);
}

/// Texel index per lane of coordinates t wrapped into [0, 1) over n texels: AlphaMask::opaque's
/// scalar operations (truncate, step down when above t, scale, truncate, clamp) on float lanes.
template <class DF, class VF>
auto texel_lanes(DF df, VF t, int n) {
  const hn::RebindToSigned<DF> di;
  const VF f = hn::Floor(t);  // exactly AlphaMask::texel's truncate-and-step-down for |t| < 2^31
  const auto i = hn::ConvertTo(di, hn::Mul(hn::Sub(t, f), hn::Set(df, float(n))));
  return hn::Min(i, hn::Set(di, n - 1));
}

/// Lanes of `live` (bit k = lane k) whose pixel centre (x = vx, y = py) is opaque in the
/// triangle's alpha mask, as bits: the U, V, W planes on double lanes, the texture coordinates as
/// float quotients and the texel indices on float lanes (AlphaAttrib's documented operations),
/// then one gather of the texels' opacity words. Lanes outside `live` read word 0 and are dropped.
template <class D, class V>
uint8_t opaque_lanes(D d, const AlphaAttrib& a, V vx, double py, uint8_t live) {
  const auto plane = [&](const PixelPlane& p) { return plane_lanes(d, p.c, p.b, p.a, py, vx); };
  const hn::Rebind<float, D> df;
  const hn::RebindToSigned<decltype(df)> di;
  const hn::RebindToUnsigned<decltype(df)> du;
  const AlphaBits& bits = *a.bits;
  const auto w = hn::DemoteTo(df, plane(a.w));
  const auto s = hn::Div(hn::DemoteTo(df, plane(a.u)), w);
  const auto t = hn::Div(hn::DemoteTo(df, plane(a.v)), w);
  const auto texel = hn::Add(hn::Mul(texel_lanes(df, t, bits.height), hn::Set(di, bits.width)), texel_lanes(df, s, bits.width));
  const auto live_f = hn::RebindMask(di, hn::LoadMaskBits(df, &live));
  // Clamped into the mask so that no lane can read outside it, whatever its coordinates were.
  const auto index = hn::IfThenElseZero(live_f, hn::Min(hn::Max(texel, hn::Zero(di)), hn::Set(di, bits.width * bits.height - 1)));
  const auto words = hn::GatherIndex(du, bits.words.data(), hn::ShiftRight<5>(index));
  const auto bit = hn::And(hn::Shr(words, hn::BitCast(du, hn::And(index, hn::Set(di, 31)))), hn::Set(du, 1u));
  uint8_t opaque = 0;
  hn::StoreMaskBits(du, hn::And(hn::RebindMask(du, live_f), hn::Ne(bit, hn::Zero(du))), &opaque);
  return opaque;
}

/// Writes the lanes `win` of one row segment (depth values `depth`) and resolves the lanes `tie`
/// (equal stored depth) by key; dp, kp point at the segment's depth and key. Returns the writes made.
template <class D, class V, class M>
size_t write_winners(D d, const RasterTri& t, V depth, M win, M tie, double* dp, uint64_t* kp) {
  const hn::RebindToUnsigned<D> du;
  if (hn::AllFalse(d, tie)) {
    hn::BlendedStore(depth, win, d, dp);
    hn::BlendedStore(hn::Set(du, t.key), hn::RebindMask(du, win), du, kp);
    return hn::CountTrue(d, win);
  }
  alignas(64) double dv[kDepthBlockSize];
  uint8_t win_bits[8], tie_bits[8];
  hn::Store(depth, d, dv);
  hn::StoreMaskBits(d, win, win_bits);
  hn::StoreMaskBits(d, tie, tie_bits);
  return size_t(write_lanes_scalar(t, dv, win_bits, tie_bits, hn::Lanes(d), dp, kp));
}

/// Offset of tile pixel (x, y) in the tile planes.
size_t plane_offset(const TileJob& job, int x, int y) { return size_t(y) * size_t(job.stride) + size_t(x); }

/// Edge values of one block column on the lanes of its first row, and their steps per row down.
template <class V>
struct EdgeRows {
  V e0, e1, e2;     ///< The three edge functions at the current row.
  V eb0, eb1, eb2;  ///< Their change per row down.
  /// Steps to the next row (exact: integer-valued doubles).
  void step() {
    e0 = hn::Add(e0, eb0);
    e1 = hn::Add(e1, eb1);
    e2 = hn::Add(e2, eb2);
  }
  /// Lanes of `lanes` inside all three edges.
  template <class D, class M>
  M inside(D d, M lanes) const {
    const auto zero = hn::Zero(d);
    return hn::And(hn::And(lanes, hn::Ge(e0, zero)), hn::And(hn::Ge(e1, zero), hn::Ge(e2, zero)));
  }
};

/// Covered rows of one opaque block column: depth-tests and writes row by row. Adds the covered
/// lanes to `fragments` and returns the writes made.
template <class D, class V, class M>
uint64_t raster_rows(D d, const RasterTri& t, const TileJob& job, TileScratch& s, int x, V vx, M lanes,
                     EdgeRows<V> e, int y_begin, int y_end, uint64_t& fragments) {
  uint64_t writes = 0;
  for (int y = y_begin; y <= y_end; ++y, e.step()) {
    const auto in = e.inside(d, lanes);
    if (hn::AllFalse(d, in)) continue;
    fragments += hn::CountTrue(d, in);
    const auto depth = depth_lanes(d, t, vx, double(job.y0 + y));
    const size_t off = plane_offset(job, x, y);
    const auto stored = hn::LoadU(d, s.depth.data() + off);
    writes += write_winners(d, t, depth, hn::And(in, hn::Gt(depth, stored)), hn::And(in, hn::Eq(depth, stored)),
                            s.depth.data() + off, s.key.data() + off);
  }
  return writes;
}

/// Covered rows of one alpha-tested block column, in three passes: the coverage and depth tests
/// of every row without branches, then the alpha tests of the rows with candidates, then the
/// writes (no per-row branch before the alpha test). Each pixel is covered once by the triangle,
/// so testing all rows before writing any is the same as row by row. Adds the covered lanes to
/// `fragments` and returns the writes made.
template <class D, class V, class M>
uint64_t raster_masked_rows(D d, const RasterTri& t, const AlphaAttrib& alpha, const TileJob& job, TileScratch& s,
                            int x, V vx, M lanes, EdgeRows<V> e, int y_begin, int y_end, uint64_t& fragments) {
  uint8_t win_bits[kDepthBlockSize], tie_bits[kDepthBlockSize], opaque_bits[kDepthBlockSize];
  int rows[kDepthBlockSize];
  int candidates = 0;
  for (int y = y_begin; y <= y_end; ++y, e.step()) {
    const auto in = e.inside(d, lanes);
    fragments += hn::CountTrue(d, in);
    const auto depth = depth_lanes(d, t, vx, double(job.y0 + y));
    const auto stored = hn::LoadU(d, s.depth.data() + plane_offset(job, x, y));
    const auto win = hn::And(in, hn::Gt(depth, stored)), tie = hn::And(in, hn::Eq(depth, stored));
    const int r = y - y_begin;
    hn::StoreMaskBits(d, win, &win_bits[r]);
    hn::StoreMaskBits(d, tie, &tie_bits[r]);
    rows[candidates] = r;
    candidates += (win_bits[r] | tie_bits[r]) != 0 ? 1 : 0;
  }
  for (int k = 0; k < candidates; ++k) {
    const int r = rows[k];
    opaque_bits[r] = opaque_lanes(d, alpha, vx, double(job.y0 + y_begin + r), uint8_t(win_bits[r] | tie_bits[r]));
  }
  uint64_t writes = 0;
  for (int k = 0; k < candidates; ++k) {
    const int r = rows[k], y = y_begin + r;
    const uint8_t win = uint8_t(win_bits[r] & opaque_bits[r]), tie = uint8_t(tie_bits[r] & opaque_bits[r]);
    const size_t off = plane_offset(job, x, y);
    writes += write_winners(d, t, depth_lanes(d, t, vx, double(job.y0 + y)), hn::LoadMaskBits(d, &win),
                            hn::LoadMaskBits(d, &tie), s.depth.data() + off, s.key.data() + off);
  }
  return writes;
}

/// Rasterises triangle `t` into the part [x_first, x_last] x [y_begin, y_end] (tile-local) of
/// one 8x8 block, which open_blocks let through. Edge values step down the rows by exact
/// additions (integer-valued doubles). Returns true when it wrote a pixel.
HWY_INLINE bool raster_block(const RasterTri& t, const AlphaAttrib* alpha, const TileJob& job, TileScratch& s,
                             TileCounters& counters, int x_first, int x_last, int y_begin, int y_end) {
  const DTag d;
  const int N = int(hn::Lanes(d));
  const double b0 = t.edge[0].b(), b1 = t.edge[1].b(), b2 = t.edge[2].b();
  const double py0 = double(job.y0 + y_begin);
  const int block_x0 = x_first / kDepthBlockSize * kDepthBlockSize;
  // Counted in locals: counters may alias the key plane (both uint64_t), which would make every
  // covered row load and store them through memory.
  uint64_t fragments = 0, writes = 0;
  for (int x = block_x0 + (x_first - block_x0) / N * N; x <= x_last; x += N) {
    const auto vx = hn::Add(hn::Set(d, double(job.x0 + x)), hn::Iota(d, 0.0));
    const EdgeRows<hn::Vec<DTag>> e{plane_lanes(d, t.edge[0].c, b0, t.edge[0].a(), py0, vx),
                                   plane_lanes(d, t.edge[1].c, b1, t.edge[1].a(), py0, vx),
                                   plane_lanes(d, t.edge[2].c, b2, t.edge[2].a(), py0, vx),
                                   hn::Set(d, b0), hn::Set(d, b1), hn::Set(d, b2)};
    auto lanes = hn::FirstN(d, size_t(std::min(x_last + 1 - x, N)));
    if (x < x_first) lanes = hn::AndNot(hn::FirstN(d, size_t(x_first - x)), lanes);
    writes += alpha != nullptr ? raster_masked_rows(d, t, *alpha, job, s, x, vx, lanes, e, y_begin, y_end, fragments)
                               : raster_rows(d, t, job, s, x, vx, lanes, e, y_begin, y_end, fragments);
  }
  counters.fragments += fragments;
  counters.writes += writes;
  return writes > 0;
}

/// The blocks of one block row (bit bx for block bx) where bin entry `e` may write, rows
/// [y_begin, y_end] (tile-local), tested on lanes of blocks: first the entry's depth bound against
/// each block's minimum `bmin[bx]`, without reading its triangle; then, with the triangle (loaded
/// into `t` on first need), over the part of each block the entry covers: its depth plane at the
/// part's corner its slopes point to (the plane's computed values are monotone in x and y, so
/// that corner holds the largest depth of the part) against the block's minimum, and each edge at
/// the corner its gradient points to (exact). bmin must be readable up to a vector past the row.
HWY_INLINE uint64_t open_blocks(const BinEntry& e, const TileSource& src, const TileJob& job, const double* bmin,
                                int y_begin, int y_end, const RasterTri*& t) {
  const DTag d;
  const int N = int(hn::Lanes(d));
  const double iy0 = double(job.y0 + y_begin), iy1 = double(job.y0 + y_end);
  const int bx_last = e.x1 / kDepthBlockSize;
  uint64_t open = 0;
  for (int bx = e.x0 / kDepthBlockSize; bx <= bx_last; bx += N) {
    const auto stored_min = hn::LoadU(d, bmin + bx);
    auto m = hn::And(hn::FirstN(d, size_t(bx_last - bx) + 1), hn::Ge(hn::Set(d, e.depth_max), stored_min));
    if (hn::AllFalse(d, m)) continue;
    if (t == nullptr) t = &src.tris[e.index];
    const auto left = hn::Mul(hn::Add(hn::Set(d, double(bx)), hn::Iota(d, 0.0)), hn::Set(d, double(kDepthBlockSize)));
    const auto x0 = hn::Add(hn::Set(d, double(job.x0)), hn::Max(left, hn::Set(d, double(e.x0))));
    const auto x1 = hn::Add(hn::Set(d, double(job.x0)),
                            hn::Min(hn::Add(left, hn::Set(d, double(kDepthBlockSize - 1))), hn::Set(d, double(e.x1))));
    const PixelPlane& p = t->depth;
    const auto nearest = plane_lanes(d, p.c, p.b, p.a, p.b >= 0 ? iy1 : iy0, p.a >= 0 ? x1 : x0);
    m = hn::AndNot(hn::Lt(nearest, stored_min), m);
    for (const EdgeFunction& f : t->edge)
      m = hn::And(m, hn::Ge(plane_lanes(d, f.c, f.b(), f.a(), f.dx >= 0 ? iy1 : iy0, f.dy <= 0 ? x1 : x0), hn::Zero(d)));
    uint8_t bits = 0;
    hn::StoreMaskBits(d, m, &bits);
    open |= uint64_t(bits) << bx;
  }
  return open;
}

/// Index of 8x8 block (bx, by) of the tile in TileScratch::block_min.
size_t block_index(const TileJob& job, int bx, int by) {
  return size_t(by) * size_t(job.stride / kDepthBlockSize) + size_t(bx);
}

/// Rasterises one bin entry into the 8x8 blocks of the tile it overlaps, skipping the blocks
/// open_blocks rules out; its RasterTri is only read when a block passes the entry's depth bound.
/// open_blocks and raster_block are forced inline into it: they run per block row and per block
/// (half a million times a frame), and inlined they keep the entry's values in registers.
void raster_entry(const BinEntry& e, const TileSource& src, const TileJob& job, TileScratch& s,
                  TileCounters& counters) {
  static_assert(256 / kDepthBlockSize <= 64, "a tile row's blocks fit one 64-bit set");
  const RasterTri* t = nullptr;
  for (int by = e.y0 / kDepthBlockSize; by <= e.y1 / kDepthBlockSize; ++by) {
    double* bmin = &s.block_min[block_index(job, 0, by)];
    const int y_begin = std::max(int(e.y0), by * kDepthBlockSize), y_end = std::min((by + 1) * kDepthBlockSize - 1, int(e.y1));
    uint64_t open = open_blocks(e, src, job, bmin, y_begin, y_end, t);
    if (open == 0) continue;
    const AlphaAttrib* alpha = t->alpha == kNoAlpha ? nullptr : &src.alphas[t->alpha];
    for (; open != 0; open &= open - 1) {
      const int bx = std::countr_zero(open);
      const int x_first = std::max(int(e.x0), bx * kDepthBlockSize);
      const int x_last = std::min((bx + 1) * kDepthBlockSize - 1, int(e.x1));
      if (raster_block(*t, alpha, job, s, counters, x_first, x_last, y_begin, y_end))
        bmin[bx] = block_minimum(s, job, bx, by);
    }
  }
}

/// False when the entry lies behind everything already drawn in its first block (a hint: blocks
/// only get nearer, so it will most likely be rejected there and in its other blocks).
bool might_draw(const BinEntry& e, const TileJob& job, const TileScratch& s) {
  return e.depth_max >= s.block_min[block_index(job, e.x0 / kDepthBlockSize, e.y0 / kDepthBlockSize)];
}

/// Clears the tile and rasterises every source triangle into it.
void RasteriseTileImpl(const TileJob& job, const TileSource* sources, size_t source_count, TileScratch& s,
                       TileCounters& counters) {
  const size_t pixels = size_t(job.stride) * size_t(job.stride);
  const size_t blocks = pixels / size_t(kDepthBlockSize * kDepthBlockSize);
  s.depth.assign(pixels, job.depth_clear);
  s.key.assign(pixels, kNoKey);
  s.block_min.assign(blocks + kDepthBlockSize, job.depth_clear);  // + a vector for open_blocks' loads
  for (size_t k = 0; k < source_count; ++k) {
    const TileSource& src = sources[k];
    for (size_t i = 0; i < src.count; ++i) {
      // A tile's triangles lie scattered over the worker's store: fetch ahead of use the ones
      // not already hidden in their first block.
      if (i + kPrefetchDistance < src.count && might_draw(src.entries[i + kPrefetchDistance], job, s)) {
        const char* ahead = reinterpret_cast<const char*>(&src.tris[src.entries[i + kPrefetchDistance].index]);
        for (size_t b = 0; b < sizeof(RasterTri); b += 64) hwy::Prefetch(ahead + b);
        hwy::Prefetch(ahead + sizeof(RasterTri) - 1);
      }
      raster_entry(src.entries[i], src, job, s, counters);
    }
  }
}

static_assert(uint32_t(kNoKey >> 32) == kNoInstance, "an empty key splits into kNoInstance");

/// split_winners for one target (the scalar tail does the same per pixel).
size_t SplitWinnersImpl(const double* depth, const uint64_t* key, size_t n, float* out_depth, uint32_t* out_instance,
                        uint32_t* out_triangle) {
  const hn::ScalableTag<uint64_t> du;
  const hn::RebindToFloat<decltype(du)> dd;
  const hn::Rebind<float, decltype(dd)> df;
  const hn::Rebind<uint32_t, decltype(du)> d32;
  const size_t N = hn::Lanes(du);
  // Vectors of the output planes go straight to memory (no read of the lines they replace) when
  // they are whole vectors of 16 bytes or more and the rows are aligned to them, as tile rows of
  // a cache-aligned VisibilityBuffer are (partial vectors store with plain stores).
  const size_t out_bytes = N * sizeof(float);
  const bool stream = out_bytes >= 16 && reinterpret_cast<uintptr_t>(out_depth) % out_bytes == 0 &&
                      reinterpret_cast<uintptr_t>(out_instance) % out_bytes == 0 &&
                      reinterpret_cast<uintptr_t>(out_triangle) % out_bytes == 0;
  size_t i = 0, hits = 0;
  for (; i + N <= n; i += N) {
    const auto k = hn::LoadU(du, key + i);
    const auto hit = hn::Ne(k, hn::Set(du, kNoKey));
    hits += hn::CountTrue(du, hit);
    const auto d = hn::DemoteTo(df, hn::IfThenElseZero(hn::RebindMask(dd, hit), hn::LoadU(dd, depth + i)));
    const auto instance = hn::TruncateTo(d32, hn::ShiftRight<32>(k));
    const auto triangle = hn::TruncateTo(d32, hn::IfThenElseZero(hit, k));
    if (stream) {
      hn::Stream(d, df, out_depth + i);
      hn::Stream(instance, d32, out_instance + i);
      hn::Stream(triangle, d32, out_triangle + i);
    } else {
      hn::StoreU(d, df, out_depth + i);
      hn::StoreU(instance, d32, out_instance + i);
      hn::StoreU(triangle, d32, out_triangle + i);
    }
  }
  for (; i < n; ++i) {
    const bool hit = key[i] != kNoKey;
    hits += hit ? 1 : 0;
    out_depth[i] = hit ? float(depth[i]) : 0.0f;
    out_instance[i] = uint32_t(key[i] >> 32);
    out_triangle[i] = hit ? uint32_t(key[i]) : 0u;
  }
  return hits;
}

/// The target this copy of the kernel was compiled for.
int64_t ActiveTargetImpl() { return HWY_TARGET; }

}  // namespace silva::render::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace silva::render {

HWY_EXPORT(RasteriseTileImpl);
HWY_EXPORT(SplitWinnersImpl);
HWY_EXPORT(ActiveTargetImpl);

void rasterise_tile(const TileJob& job, std::span<const TileSource> sources, TileScratch& scratch,
                    TileCounters& counters) {
  HWY_DYNAMIC_DISPATCH(RasteriseTileImpl)(job, sources.data(), sources.size(), scratch, counters);
}

size_t split_winners(const double* depth, const uint64_t* key, size_t n, float* out_depth, uint32_t* out_instance,
                     uint32_t* out_triangle) {
  return HWY_DYNAMIC_DISPATCH(SplitWinnersImpl)(depth, key, n, out_depth, out_instance, out_triangle);
}

int64_t raster_simd_target() { return HWY_DYNAMIC_DISPATCH(ActiveTargetImpl)(); }

}  // namespace silva::render
#endif  // HWY_ONCE

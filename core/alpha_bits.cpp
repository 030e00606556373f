#include "core/alpha_bits.hpp"

#include <string>

#include "core/error.hpp"

namespace silva {

AlphaBits AlphaBits::of(const AlphaMask& mask) {
  const size_t texels = size_t(mask.width) * size_t(mask.height);
  if (mask.width < 1 || mask.height < 1 || mask.alpha.size() != texels)
    throw InputError("alpha mask of " + std::to_string(mask.width) + "x" + std::to_string(mask.height) +
                     " texels holds " + std::to_string(mask.alpha.size()) + " alpha values (needs width*height >= 1)");
  AlphaBits bits;
  bits.width = mask.width;
  bits.height = mask.height;
  bits.words.assign((texels + 31) / 32, 0u);
  for (size_t i = 0; i < texels; ++i)
    if (mask.opaque_texel(int(i))) bits.words[i / 32] |= 1u << (i % 32);
  return bits;
}

}  // namespace silva

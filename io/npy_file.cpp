#include "io/npy_file.hpp"

#include <cstring>

namespace silva::io {

std::vector<uint8_t> npy_file(const std::string& descr, std::span<const size_t> shape, std::span<const uint8_t> data) {
  std::string dims;  // "H, W"; a 1-d shape keeps its comma: "N,"
  for (size_t k = 0; k < shape.size(); ++k) dims += (k ? ", " : "") + std::to_string(shape[k]);
  if (shape.size() == 1) dims += ",";
  std::string header = "{'descr': '" + descr + "', 'fortran_order': False, 'shape': (" + dims + "), }";
  const size_t unpadded = 10 + header.size() + 1;  // magic, version, length, header, newline
  header.append((64 - unpadded % 64) % 64, ' ');
  header += '\n';
  const std::string prefix = std::string("\x93NUMPY\x01\x00", 8) + char(header.size() & 0xff) + char(header.size() >> 8);
  std::vector<uint8_t> out(prefix.size() + header.size() + data.size());
  std::memcpy(out.data(), prefix.data(), prefix.size());
  std::memcpy(out.data() + prefix.size(), header.data(), header.size());
  if (!data.empty()) std::memcpy(out.data() + prefix.size() + header.size(), data.data(), data.size());
  return out;
}

}  // namespace silva::io

#include "io/image_codecs.hpp"

#include "core/imgcodecs_symbols.hpp"
#include "core/shared_library.hpp"

namespace silva::io {

cv::Mat decode_image(cv::InputArray bytes, int flags) {
  static auto* const decode = shared_library_function<cv::Mat(const cv::_InputArray&, int)>(kImgcodecsLibrary, kImdecodeSymbol);
  return decode(bytes, flags);
}

cv::Mat read_image_file(const std::string& path, int flags) {
  static auto* const read = shared_library_function<cv::Mat(const std::string&, int)>(kImgcodecsLibrary, kImreadSymbol);
  return read(path, flags);
}

bool encode_image(const std::string& extension, cv::InputArray image, std::vector<uint8_t>& out,
                  const std::vector<int>& params) {
  static auto* const encode =
      shared_library_function<bool(const std::string&, const cv::_InputArray&, std::vector<uchar>&, const std::vector<int>&)>(
          kImgcodecsLibrary, kImencodeSymbol);
  return encode(extension, image, out, params);
}

}  // namespace silva::io

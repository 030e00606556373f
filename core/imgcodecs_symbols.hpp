#pragma once
/// @file Where OpenCV's image codecs (imgcodecs) live, for the readers and writers that open them at first
/// need: imgcodecs loads GDAL and some 130 libraries, 0.13 s at every start of a program linked to it.

namespace silva {

/// The imgcodecs library file Silva was built against (CMake's SILVA_IMGCODECS_LIBRARY).
inline constexpr const char* kImgcodecsLibrary = SILVA_IMGCODECS_LIBRARY;

/// cv::imdecode(const cv::_InputArray&, int), by its Itanium C++ ABI name.
inline constexpr const char* kImdecodeSymbol = "_ZN2cv8imdecodeERKNS_11_InputArrayEi";

/// cv::imread(const std::string&, int), by its Itanium C++ ABI name (GCC's std::__cxx11 string).
inline constexpr const char* kImreadSymbol = "_ZN2cv6imreadERKNSt7__cxx1112basic_stringIcSt11char_traitsIcESaIcEEEi";

/// cv::imencode(const std::string&, const cv::_InputArray&, std::vector<uchar>&, const std::vector<int>&),
/// by its Itanium C++ ABI name.
inline constexpr const char* kImencodeSymbol =
    "_ZN2cv8imencodeERKNSt7__cxx1112basic_stringIcSt11char_traitsIcESaIcEEERKNS_11_InputArrayERSt6vectorIhSaIhEERKSB_"
    "IiSaIiEE";

}  // namespace silva

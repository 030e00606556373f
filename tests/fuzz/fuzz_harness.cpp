// One libFuzzer harness: built once per target with SILVA_FUZZ_TARGET naming it (tests/fuzz/CMakeLists.txt).
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "fuzz_entries.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const silva::fuzz::FuzzTarget* target = [] {
    for (const auto& t : silva::fuzz::fuzz_targets())
      if (std::strcmp(t.name, SILVA_FUZZ_TARGET) == 0) return &t;
    std::abort();
  }();
  silva::fuzz::run_fuzz_input(*target, std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}

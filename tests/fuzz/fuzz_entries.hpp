#pragma once
/// @file The entry points of the fuzz harnesses (docs/fuzzing.md): each feeds one input to
/// one reader the way the CLI does. Bad input may be refused (InputError, IoError); anything else
/// (another exception, a crash, a sanitizer report) is a bug. The libFuzzer harnesses and the
/// corpus replay test (tests/app/fuzz_corpus_test.cpp) share them.
#include <span>
#include <string_view>

namespace silva::fuzz {

/// One fuzz target: its name (also its corpus folder tests/fuzz/corpus/<name>/) and entry point.
struct FuzzTarget {
  const char* name;                     ///< Target name.
  void (*run)(std::string_view input);  ///< Feeds one input; throws only for bad input.
};

/// Every fuzz target.
std::span<const FuzzTarget> fuzz_targets();

/// Runs `target` on `input`; true when it was accepted, false when refused as bad input. Any other
/// exception propagates.
bool run_fuzz_input(const FuzzTarget& target, std::string_view input);

}  // namespace silva::fuzz

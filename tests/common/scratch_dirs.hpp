#pragma once
/// @file Scratch folders of tests: removed at the end of a test program whose tests all passed,
/// kept (and named on stderr) when one failed, so what it left can be looked at.
#include <filesystem>

namespace silva::test {

/// Removes `dir` (and everything in it) when the test program ends with every test passed.
void remove_when_passed(const std::filesystem::path& dir);

}  // namespace silva::test

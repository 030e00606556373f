#pragma once
/// @file Shortest round-trip text for numbers, in messages and in printed TOML.
#include <string>

namespace silva::pipeline {

/// Shortest text that reads back as `v`; whole numbers below 1e15 without exponent ("150", "0.05").
std::string format_number(double v);

/// Like format_number, but always a TOML float ("90.0", "0.05", "1e-07").
std::string format_toml_float(double v);

}  // namespace silva::pipeline

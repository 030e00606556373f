#pragma once
/// @file The harness measures the pipeline: pipeline/'s names (config, console, schedule) are visible in
/// silva::bench without qualification.
namespace silva::pipeline {}

namespace silva::bench {
using namespace silva::pipeline;  // NOLINT(google-build-using-namespace): bench/ is the layer above pipeline/
}  // namespace silva::bench

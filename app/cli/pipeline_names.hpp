#pragma once
/// @file The commands are written in the pipeline's terms: pipeline/'s names (config, console, schedule)
/// are visible in silva::app without qualification.
namespace silva::pipeline {}

namespace silva::app {
using namespace silva::pipeline;  // NOLINT(google-build-using-namespace): app/ is the layer above pipeline/
}  // namespace silva::app

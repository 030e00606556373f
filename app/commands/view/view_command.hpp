#pragma once
/// @file What `silva view` asks of the pipeline, and its run function.
#include <string>

#include "pipeline/config/config_loader.hpp"
#include "pipeline/console/reporter.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

/// `silva view`: a local web page exploring the world, with captures into the output folder.
struct ViewRequest {
  ConfigSources sources;           ///< --config, --set, --seed (checked by the session).
  std::string host = "127.0.0.1";  ///< --host: the address to listen on.
  int port = 8080;                 ///< --port (0 = any free port, printed).
};

/// Serves the view until Ctrl-C (then throws Interrupted: exit 130). Throws InputError / IoError.
int run_view(const ViewRequest& request, const Reporter& reporter);

}  // namespace silva::app

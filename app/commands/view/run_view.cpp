// `silva view` after the CLI checks: build the first world, serve the page until Ctrl-C.
#include <chrono>
#include <thread>

#include "pipeline/console/interrupt.hpp"
#include "app/commands/view/view_command.hpp"
#include "app/commands/view/view_explorer.hpp"
#include "pipeline/config/data_path.hpp"
#include "core/error.hpp"
#include "core/stopwatch.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

int run_view(const ViewRequest& request, const Reporter& reporter) {
  const Stopwatch clock;
  ViewExplorer explorer(request.sources);
  web::ViewServer server(data_path("web/page"));
  explorer.install(server);
  int port = 0;
  try {
    port = server.bind(request.host, request.port);
  } catch (const std::runtime_error& e) {
    throw IoError(std::string(e.what()) + " (is the port in use? try --port 0)");
  }
  // The token in the URL is what lets the page change settings and capture (web/view_server.hpp).
  const std::string url = "http://" + request.host + ":" + std::to_string(port) + "/?token=" + server.token();
  reporter.note("silva: seed " + std::to_string(explorer.world()->loaded().config.seed) + ", ready in " +
                std::to_string(int(clock.seconds() * 1000)) + " ms");
  reporter.result({{"ok", true}, {"url", url}, {"port", port}}, "silva view: " + url + " (Ctrl-C to stop)");
  begin_writing();  // from here a capture may be writing: Ctrl-C stops the server cleanly (a second one at once)
  std::thread serving([&] { server.run(); });
  while (!interrupt_requested()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  server.stop();
  serving.join();
  throw Interrupted("interrupted: the view stopped (its captures, if any, are complete in " +
                    explorer.world()->loaded().config.output.dir + ")");
}

}  // namespace silva::app

// `silva version`: the version, git revision and SIMD targets of this build.
#include <memory>

#include "app/cli/command_options.hpp"
#include "pipeline/console/reporter.hpp"
#include "app/cli/subcommands.hpp"
#include "pipeline/console/version.hpp"
#include "app/cli/pipeline_names.hpp"
#include "app/cli/simd_limit.hpp"

namespace silva::app {

Handler add_version_command(CLI::App& root) {
  auto output = std::make_shared<OutputFlags>();
  CLI::App* cmd = root.add_subcommand("version", "Print Silva's version, git revision and SIMD targets.");
  add_output_flags(*cmd, *output);
  cmd->footer("Examples:\n  silva version\n  silva version --json   # {\"version\",\"git_revision\",\"simd_targets\"}");
  return [output] {
    const std::vector<std::string> targets = simd_targets();
    std::string text = version_line() + "\nSIMD targets:";
    for (const std::string& t : targets) text += " " + t;
    const nlohmann::json summary = {
        {"version", silva_version()}, {"git_revision", git_revision()}, {"simd_targets", targets}};
    Reporter(*output).result(summary, text);
    return 0;
  };
}

}  // namespace silva::app

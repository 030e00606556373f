// `silva version`: the version, git revision and SIMD targets of this build.
#include <memory>

#include <hwy/targets.h>

#include "app/cli/command_options.hpp"
#include "pipeline/console/reporter.hpp"
#include "app/cli/subcommands.hpp"
#include "pipeline/console/version.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

namespace {

/// Highway targets this build can dispatch to on this CPU, best first.
std::vector<std::string> simd_targets() {
  std::vector<std::string> names;
  const uint64_t usable = static_cast<uint64_t>(hwy::SupportedTargets() & HWY_TARGETS);
  for (uint64_t bit = 1; bit != 0; bit <<= 1) {
    if ((usable & bit) != 0) names.emplace_back(hwy::TargetName(static_cast<int64_t>(bit)));
  }
  return names;  // Highway numbers better targets with lower bits
}

}  // namespace

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

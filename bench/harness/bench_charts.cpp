#include "bench/harness/bench_charts.hpp"

#include <sys/wait.h>

#include <cstdlib>

#include "pipeline/config/data_path.hpp"
#include "bench/harness/pipeline_names.hpp"

namespace silva::bench {

std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

int run_shell(const std::string& command) {
  const int status = std::system(command.c_str());
  return status == -1 || !WIFEXITED(status) ? -1 : WEXITSTATUS(status);
}

ChartRun draw_charts(const std::filesystem::path& results_json) {
  const std::filesystem::path script = data_path("scripts/bench_charts.py");
  std::string args = " ";  // built by appending: GCC 12 warns falsely (-Wrestrict) on " " + string
  args += shell_quote(script.string());
  args += " ";
  args += shell_quote(results_json.string());
  // The first python3 on PATH may be a private one (pyenv, venv) without Debian's matplotlib.
  for (const std::string& python : {std::string("python3"), std::string("/usr/bin/python3")}) {
    std::string check = python;
    check.append(" -c 'import matplotlib, numpy' >/dev/null 2>&1");
    if (run_shell(check) != 0) continue;
    const std::string command = python + args;
    if (run_shell(command + " 1>&2") != 0) return {false, "the chart script failed; rerun: " + command};
    return {true, "charts drawn by " + command};
  }
  return {false, "python3 with matplotlib and numpy not found; draw the charts later with: python3" + args +
                     " (Debian: apt-get install python3-matplotlib python3-numpy)"};
}

}  // namespace silva::bench

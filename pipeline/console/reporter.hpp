#pragma once
/// @file How a command talks: notes and progress on stderr, its result on stdout.
#include <string>

#include <nlohmann/json.hpp>


namespace silva::pipeline {

/// --json (one summary object on stdout) and --quiet (no progress on stderr): every command.
struct OutputFlags {
  bool json = false;   ///< Print one machine-readable JSON object on stdout.
  bool quiet = false;  ///< Print no progress or notes on stderr (errors still print).
};

/// Prints a command's messages according to --json and --quiet.
class Reporter {
 public:
  /// A reporter for a command run with `flags`.
  explicit Reporter(OutputFlags flags) : flags_(flags) {}
  /// A note or progress line on stderr, unless --quiet.
  void note(const std::string& line) const;
  /// A warning on stderr ("silva: warning: ..."), unless --quiet.
  void warn(const std::string& line) const;
  /// The result: with --json the `summary` object on stdout, else `text` on stdout (if not empty).
  void result(const nlohmann::json& summary, const std::string& text) const;
  /// The flags this reporter follows.
  const OutputFlags& flags() const { return flags_; }

 private:
  OutputFlags flags_;
};

}  // namespace silva::pipeline

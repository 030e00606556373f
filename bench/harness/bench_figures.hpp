#pragma once
/// @file One measured figure of `silva bench` beside the thesis's, and the thesis tables it reproduces.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace silva::bench {

/// What a figure's time paid for (0 = not applicable).
struct WorkCounts {
  uint64_t objects = 0;    ///< Placed objects in the built world(s).
  uint64_t chunks = 0;     ///< Chunks built or streamed.
  uint64_t triangles = 0;  ///< Terrain triangles (generation) or triangles submitted (capture).
  uint64_t frames = 0;     ///< Capture sets rendered and written.
  uint64_t pixels = 0;     ///< frames x width x height.
  uint64_t bytes = 0;      ///< Bytes written to disk.
};

/// One measured point: Silva's time, the thesis's time for the same x, their ratio, the work done.
struct Figure {
  std::string table;                ///< Table key: "5.1".."5.9", "autopilot", "threads-generation", ...
  std::string x;                    ///< The varied value as text ("5", "1920x1080", "rgb", "2").
  double silva_s = 0;               ///< Silva's time, seconds.
  std::optional<double> thesis_s;   ///< The thesis's time for this x, seconds (none for our own tables).
  bool extrapolated = false;        ///< True when silva_s is scaled from a smaller measured run.
  std::string note;                 ///< How it was measured, when not obvious.
  WorkCounts work;                  ///< Work counts.
  nlohmann::json breakdown = nlohmann::json::object();  ///< Phase seconds and other details.
  /// silva_s / thesis_s (below 1 = Silva faster), or none without a thesis figure.
  std::optional<double> ratio() const;
};

/// The thesis's Chapter 5 tables (bench/thesis-tables.json).
class ThesisTables {
 public:
  /// Parses the thesis-tables.json document. Throws InputError when it lacks "tables".
  explicit ThesisTables(nlohmann::json doc);
  /// Reads bench/thesis-tables.json from `path`. Throws InputError naming the file.
  static ThesisTables load(const std::filesystem::path& path);
  /// The thesis time in seconds of `table` at x (as text: "5", "true", "1920x1080"), if listed.
  std::optional<double> seconds(const std::string& table, const std::string& x) const;
  /// The table's title ("" when unknown).
  std::string title(const std::string& table) const;
  /// The table's x values as text, in the thesis's order.
  std::vector<std::string> xs(const std::string& table) const;
  /// The thesis's estimate of the full autopilot, seconds.
  double autopilot_estimate_s() const;
  /// The thesis machine's description.
  std::string machine() const;

 private:
  nlohmann::json doc_;
};

/// A figure as JSON: table, x, silva_s, thesis_s (or null), ratio (or null), extrapolated, note,
/// work {objects, chunks, triangles, frames, pixels, bytes}, breakdown.
nlohmann::json figure_json(const Figure& f);

/// Text of a JSON scalar as used for x ("5", "true", "720x480").
std::string x_text(const nlohmann::json& v);

}  // namespace silva::bench

#pragma once
/// @file The resource limits every input reader enforces (README "Bad input"): one place for the
/// nesting depth, file sizes, counts and coordinate ranges, and the checks that apply them.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace silva::limits {

/// Deepest nesting of JSON arrays/objects accepted in any input file (Silva's own formats need 5).
inline constexpr int kMaxJsonDepth = 64;
/// Largest input file read whole (config, pose file, ontology, lighting presets, library.json).
inline constexpr std::uintmax_t kMaxInputFileBytes = 256ull << 20;
/// Most frames one sequence may hold: frame files are numbered with six digits.
inline constexpr int kMaxFramesPerSequence = 1'000'000;
/// Largest |x| and |y| of a custom pose, metres: chunk indices and float32 terrain stay exact inside it.
inline constexpr double kMaxPoseCoordinate = 100'000.0;
/// Largest |z| of a custom pose, metres.
inline constexpr double kMaxPoseHeight = 10'000.0;
/// Largest |coordinate| of an imported asset's vertex or collision proxy, metres.
inline constexpr double kMaxAssetCoordinate = 1'000.0;
/// Largest collision proxy of an asset: radius or half extent, and cylinder or capsule length, metres (a fallen
/// tree's trunk is ~30 m long); larger proxies would make every neighbouring object collide with them.
inline constexpr double kMaxProxySize = 40.0;
/// Largest texture an asset may embed or reference, pixels per side.
inline constexpr int kMaxTextureSide = 16'384;
/// Placement points one frame may evaluate without --force (2e6 take about a minute on one core).
inline constexpr double kMaxPlacementPointsPerFrame = 2e6;
/// Share of this machine's physical memory a run's estimate may take without --force.
inline constexpr double kMaxMemoryShare = 0.75;
/// Longest piece of an offending value quoted in an error line.
inline constexpr size_t kMaxQuotedChars = 80;

/// The deepest nesting of `[`/`{` in JSON text, strings skipped; stops counting past kMaxJsonDepth + 1.
int json_nesting_depth(std::string_view text);

/// Throws InputError "<where>: nested deeper than 64 levels" when `text` is.
void check_json_depth(std::string_view text, const std::string& where);

/// Reads a whole input file: InputError naming `path` when it is missing, not a regular file,
/// unreadable or larger than kMaxInputFileBytes. `what` names the file's role ("pose file").
std::string read_input_file(const std::filesystem::path& path, const std::string& what);

/// `text` cut to kMaxQuotedChars characters ("..." appended when cut) for an error line.
std::string quoted_prefix(std::string_view text);

}  // namespace silva::limits

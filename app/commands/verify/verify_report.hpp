#pragma once
/// @file `silva verify`'s certificate: verify.json (the numbers) and VERIFY.md (the same in words, with
/// the thresholds, a per-class table and the verdict).
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "app/commands/verify/verify_command.hpp"
#include "app/commands/verify/verify_compare.hpp"
#include "app/commands/verify/verify_lidar.hpp"
#include "io/dataset_reader.hpp"

namespace silva::app {

/// What a verification counted, beside the request that set its thresholds.
struct VerifyCounts {
  VerifyTally pixels;                 ///< Every compared pixel of every checked frame.
  std::optional<LidarTally> lidar;    ///< The scans' points, when the dataset has output type lidar.
  nlohmann::json frames = nlohmann::json::array();  ///< Per checked frame: sequence, frame, its own numbers.
  std::string depth_source;           ///< "depth_exr" or "depth" (the mm PNG).
  bool instances = false;             ///< Instance images were compared.
  bool normals = false;               ///< Normal images were compared.
};

/// The numbers of one frame's tally as verify.json writes them: pixels, class agreement (interior,
/// silhouette), depth agreement, instance agreement (null when not compared), the largest disagreements.
nlohmann::json tally_summary(const VerifyTally& tally, bool instances);

/// verify.json's object: dataset, thresholds, totals, per class, per frame, LiDAR, verdict.
nlohmann::json verify_json(const io::Dataset& dataset, const VerifyRequest& request, const VerifyCounts& counts);

/// VERIFY.md: the certificate in words.
std::string verify_markdown(const nlohmann::json& verify);

}  // namespace silva::app

#pragma once
/// @file The dataset card's class map under the cameras: the world around them, from the run's own schedule or
/// rebuilt from the config the run marker records.
#include <optional>
#include <string>

#include "app/commands/card/card_command.hpp"
#include "io/dataset_card.hpp"
#include "world/class_map.hpp"

namespace silva::app {

/// Metres around each camera that the class map under them shows (the map's box spans them all).
inline constexpr double kMapMargin = 16.0;
/// Side of the pose map's plot, pixels.
inline constexpr int kMapSize = 480;

/// The class map under the cameras, or why there is none.
struct CameraMap {
  std::optional<world::ClassMap> map;  ///< The world's class map around the cameras.
  std::string missing;                 ///< Why there is no map ("" when there is one).
};

/// The class map of the chunks within kMapMargin of a camera (`c.positions`): from the run's
/// own world when `in` has it, else from the world rebuilt from the config the run marker records, when the
/// marker's identity (config, asset library, pose file) still holds.
CameraMap camera_map(const io::Dataset& d, const io::CardCounts& c, const CardInputs& in);

}  // namespace silva::app

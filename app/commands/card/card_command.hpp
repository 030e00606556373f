#pragma once
/// @file The dataset card: what a run hands it, the writer generate and merge call, and `silva card`'s run function.
#include <filesystem>

#include "io/dataset_card.hpp"
#include "pipeline/console/reporter.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::pipeline {
class WorldSchedule;
struct RunSetup;
}  // namespace silva::pipeline

namespace silva::app {

/// What a generate run hands the card so that it reads less back: the label counts of the frames it wrote,
/// and its world (schedule and setup) for the class map under the cameras. Empty: everything is read from
/// the dataset, and the world is rebuilt from the config its run marker records.
struct CardInputs {
  const io::KnownCounts* known = nullptr;  ///< Label counts of the frames this process wrote.
  pipeline::WorldSchedule* schedule = nullptr;       ///< The run's schedule (its chunk cache).
  const pipeline::RunSetup* setup = nullptr;         ///< The run's loaded inputs (library, ontology, world context).
};

/// Writes <run_dir>/CARD.md, card.json and card_*.png for a finished dataset (also at the end of generate
/// and merge). Throws InputError / IoError.
void write_card(const std::filesystem::path& run_dir, const CardInputs& inputs = {});
/// `silva card`: write_card and report; returns the exit code. Throws InputError / IoError.
int run_card(const std::filesystem::path& run_dir, const Reporter& reporter);

}  // namespace silva::app

#pragma once
/// @file Prepare phase, last step: the next frame's missing view chunks generated in the background while
/// the current frame renders (system "prefetch_chunks"); the next Stream phase takes them.
#include <tbb/task_group.h>

#include <memory>
#include <vector>

#include "ecs/world.hpp"
#include "world/chunk_content.hpp"
#include "world/world_context.hpp"

namespace silva::systems {

/// Resource: chunks the cache lacks for the next frame's view, being generated as the cache would hold them
/// (world::drawable_chunk).
class PrefetchedChunks {
 public:
  PrefetchedChunks() = default;
  PrefetchedChunks(const PrefetchedChunks&) = delete;
  PrefetchedChunks& operator=(const PrefetchedChunks&) = delete;
  PrefetchedChunks(PrefetchedChunks&&) = default;
  PrefetchedChunks& operator=(PrefetchedChunks&&) = delete;
  /// Waits for chunks still being made (their errors dropped).
  ~PrefetchedChunks();
  /// Starts generating `coords` (sorted) in the background, after waiting for any earlier start.
  void start(const world::WorldContext& ctx, std::vector<ChunkCoord> coords);
  /// The generated chunks when `wanted` (sorted) is exactly what was started, in that order; else none (and the
  /// started ones are dropped). Waits for them; rethrows an error of their generation.
  std::vector<std::shared_ptr<ChunkContent>> take(const std::vector<ChunkCoord>& wanted);
  /// The chunks started and not yet taken or dropped.
  const std::vector<ChunkCoord>& started() const;

 private:
  /// One start's chunks and the tasks making them (on the heap: the tasks write into it while this moves).
  struct Batch {
    std::vector<ChunkCoord> coords;
    std::vector<std::shared_ptr<ChunkContent>> contents;
    tbb::task_group work;
  };
  /// Waits for the batch's tasks, dropping their errors.
  void drop_batch();

  std::unique_ptr<Batch> batch_;
};

/// Registers "prefetch_chunks" (phase Prepare, after prepare_scene) and its PrefetchedChunks resource: when a
/// camera follows the active one in the CaptureQueue and none are being made, starts generating the chunks the
/// cache lacks for the next camera that is not of the active frame's view fan (those stream nothing new), so
/// they are made while the active frame (and the rest of its fan) renders.
void install_prefetch_chunks(ecs::World& world);

}  // namespace silva::systems

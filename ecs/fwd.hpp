#pragma once
/// @file Forward declarations of the ECS engine's types (namespace silva::ecs).
#include <cstddef>
#include <cstdint>

namespace silva::ecs {

struct Entity;
class EntityAllocator;
class SparseSet;
template <class T> class Pool;
template <class... Ts> class View;
class Registry;
struct PendingEntity;
struct ApplyResult;
class CommandBuffer;
class Resources;
class Access;
struct System;
struct SystemStats;
class SystemContext;
class SystemBuilder;
struct ScheduleConflict;
class Scheduler;
class World;
class Error;
class ScheduleError;

/// Entities per chunk in chunked parallel iteration; boundaries never depend on thread count.
inline constexpr std::size_t kDefaultChunkSize = 4096;

}  // namespace silva::ecs

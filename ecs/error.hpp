#pragma once
/// @file Exceptions thrown by the ECS engine: misuse is reported, never undefined behaviour.
#include <stdexcept>
#include <string>

namespace silva::ecs {

/// Misuse of the ECS (stale handle, missing component or resource, undeclared access).
class Error : public std::logic_error {
 public:
  /// Builds the error from a one-line message.
  explicit Error(const std::string& message) : std::logic_error(message) {}
};

/// A schedule that cannot be built: conflicting or badly ordered systems.
class ScheduleError : public Error {
 public:
  /// Builds the error from a message naming the systems and components involved.
  explicit ScheduleError(const std::string& message) : Error(message) {}
};

}  // namespace silva::ecs

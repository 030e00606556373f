#pragma once
/// @file An environment variable set for a test's scope, restored after it.
#include <cstdlib>
#include <optional>
#include <string>

namespace silva::test {

/// Sets an environment variable for the lifetime of the object (children inherit it), then
/// restores its earlier value (or unsets it when it had none).
class ScopedEnv {
 public:
  /// Sets `name` to `value`.
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    ::setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (old_)
      ::setenv(name_, old_->c_str(), 1);
    else
      ::unsetenv(name_);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;                ///< The variable.
  std::optional<std::string> old_;  ///< Its value before, if it had one.
};

}  // namespace silva::test

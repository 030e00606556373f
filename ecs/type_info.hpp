#pragma once
/// @file Dense runtime ids and readable names for component and resource types.
#include <atomic>
#include <cstdint>
#include <string_view>
#include <type_traits>

namespace silva::ecs {

namespace detail {
/// Next unused type id; ids only index storage, they never reach any output.
inline std::atomic<std::uint32_t> next_type_id{0};

/// The id of an unqualified type, assigned on first use.
template <class T>
std::uint32_t unqualified_type_id() {
  static const std::uint32_t id = next_type_id.fetch_add(1, std::memory_order_relaxed);
  return id;
}

/// The compiler's spelling of T, cut out of the function signature.
template <class T>
constexpr std::string_view raw_type_name() {
  std::string_view s = __PRETTY_FUNCTION__;
  const auto start = s.find("T = ") + 4;
  const auto end = s.find_first_of(";]", start);
  return s.substr(start, end - start);
}
}  // namespace detail

/// A small dense id for T (const/volatile ignored), stable for the life of the program.
template <class T>
std::uint32_t type_id() {
  return detail::unqualified_type_id<std::remove_cv_t<T>>();
}

/// The readable name of T (const/volatile ignored), e.g. "game::Position", for messages.
template <class T>
constexpr std::string_view type_name() {
  return detail::raw_type_name<std::remove_cv_t<T>>();
}

}  // namespace silva::ecs

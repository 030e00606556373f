#pragma once
/// @file A headless Chromium driven over its DevTools pipe (--remote-debugging-pipe: JSON messages
/// ended by a NUL byte on file descriptors 3 and 4), for the browser test of `silva view`.
#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace silva::test {

/// The Chromium binary to drive: $SILVA_CHROMIUM, else chromium or chromium-browser on the PATH; nullopt when none.
std::optional<std::filesystem::path> find_chromium();

/// One headless Chromium with one page attached.
class DevtoolsBrowser {
 public:
  /// Starts `chromium` headless with a fresh profile under `scratch`, opens `url` and attaches to
  /// it. Throws std::runtime_error when Chromium does not answer.
  DevtoolsBrowser(const std::filesystem::path& chromium, const std::filesystem::path& scratch, const std::string& url);
  /// Closes the browser and waits for it.
  ~DevtoolsBrowser();
  DevtoolsBrowser(const DevtoolsBrowser&) = delete;
  DevtoolsBrowser& operator=(const DevtoolsBrowser&) = delete;

  /// Sends a DevTools command to the page (or to the browser when `to_browser`); returns its
  /// result. Throws std::runtime_error on an error answer or after a 30 s silence.
  nlohmann::json call(const std::string& method, const nlohmann::json& params = nlohmann::json::object(),
                      bool to_browser = false);

  /// Evaluates a JavaScript expression in the page (promises awaited); returns its value.
  nlohmann::json eval(const std::string& expression);

  /// Evaluates `expression` every 50 ms until it is true; false after `timeout`.
  bool wait_for(const std::string& expression, std::chrono::milliseconds timeout);

  /// Presses and holds `key` (a letter) for `hold`, as typed on the focused element.
  void hold_key(char key, std::chrono::milliseconds hold);

 private:
  /// The next whole message from Chromium (empty when none came within `timeout_ms`).
  std::string read_message(int timeout_ms);

  pid_t pid_ = -1;
  int to_browser_ = -1;    ///< Our end of fd 3.
  int from_browser_ = -1;  ///< Our end of fd 4.
  std::string buffer_;     ///< Bytes read past the last message.
  int next_id_ = 1;
  std::string session_;    ///< The page's session id.
};

}  // namespace silva::test

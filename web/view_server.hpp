#pragma once
/// @file The local HTTP server of `silva view` (cpp-httplib): serves the page of web/page/ and the
/// routes the command registers, nothing else. Bounded: a fixed pool of worker threads, read and
/// write timeouts, small request bodies, and a cap on the requests each route works on at once
/// (the rest are answered 503 at once, so a slow or greedy client never queues work).
#include <atomic>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace httplib {
class Server;
}

namespace silva::web {

/// One request as a route sees it.
struct Request {
  std::map<std::string, std::string> params;  ///< Query parameters (the last of repeated names).
  std::string body;                           ///< Request body (POST).
};

/// One answer.
struct Reply {
  int status = 200;                                          ///< HTTP status.
  std::string content_type = "application/json";             ///< MIME type of `body`.
  std::string body;                                          ///< Payload.
  std::vector<std::pair<std::string, std::string>> headers;  ///< Extra headers.
};

/// A route's handler; may throw (answered 500 with the message).
using Route = std::function<Reply(const Request&)>;

/// The files of the page, served at "/" (index.html), "/view.js" and "/view.css".
inline constexpr const char* kPageFiles[] = {"index.html", "view.js", "view.css"};

/// Worker threads answering requests: a connection holds one while its request arrives, so several slow
/// clients (kReadTimeoutSeconds between bytes at most) cannot hold every thread.
inline constexpr int kServerThreads = 32;
/// Longest wait for the next bytes of a request, or for a client to take the answer, seconds.
inline constexpr int kReadTimeoutSeconds = 2;
/// The header a state-changing (POST) request carries the launch token in.
inline constexpr const char* kTokenHeader = "X-Silva-Token";
/// Largest request body accepted, bytes.
inline constexpr std::size_t kMaxBodyBytes = 64 * 1024;

/// The server: page files read once at construction, then routes added, bound, run.
class ViewServer {
 public:
  /// Reads the page files of `page_dir` (each of kPageFiles). Throws std::runtime_error naming a missing one.
  explicit ViewServer(const std::filesystem::path& page_dir);
  ~ViewServer();
  ViewServer(const ViewServer&) = delete;
  ViewServer& operator=(const ViewServer&) = delete;

  /// Answers GET `path` with `route`, working on at most `max_in_flight` requests at once.
  void get(const std::string& path, Route route, int max_in_flight = 2);
  /// Answers POST `path` with `route`, working on at most `max_in_flight` requests at once; only requests with
  /// the launch token in kTokenHeader, JSON bodies and no foreign Origin reach it (403 otherwise).
  void post(const std::string& path, Route route, int max_in_flight = 2);

  /// Binds `host`:`port` (0 = any free port); returns the bound port. Throws std::runtime_error.
  int bind(const std::string& host, int port);
  /// Serves until stop(); call after bind().
  void run();
  /// Makes run() return (from any thread).
  void stop();
  /// This launch's random token (32 hex digits); the page URL carries it as ?token=.
  const std::string& token() const { return token_; }

 private:
  /// A new in-flight counter for one route.
  std::atomic<int>& new_counter();

  std::unique_ptr<httplib::Server> server_;
  std::vector<std::unique_ptr<std::atomic<int>>> in_flight_;  ///< One counter per route.
  std::string token_;                                          ///< See token().
};

}  // namespace silva::web

#include "web/view_server.hpp"

#include <httplib.h>

#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string_view>

namespace silva::web {

namespace fs = std::filesystem;

namespace {

/// The MIME type of a page file by its extension.
std::string mime_type(const fs::path& file) {
  const std::string ext = file.extension().string();
  if (ext == ".html") return "text/html; charset=utf-8";
  if (ext == ".js") return "text/javascript; charset=utf-8";
  return "text/css; charset=utf-8";
}

/// The whole file, or std::runtime_error naming it.
std::string read_page_file(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("the page file " + file.string() + " is missing (set SILVA_DATA to the source folder)");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Headers every answer carries: the page loads nothing from elsewhere.
void set_common_headers(httplib::Response& res) {
  res.set_header("Content-Security-Policy", "default-src 'self'; img-src 'self' blob: data:");
  res.set_header("X-Content-Type-Options", "nosniff");
  res.set_header("Cache-Control", "no-store");
}

/// Decrements a counter when it goes out of scope.
struct Release {
  std::atomic<int>& counter;
  ~Release() { --counter; }
};

/// 128 random bits as 32 hex digits, from the operating system's entropy source.
std::string random_token() {
  std::random_device entropy;
  std::string hex;
  for (int i = 0; i < 4; ++i) {
    char word[9];
    std::snprintf(word, sizeof word, "%08x", unsigned(entropy()));
    hex += word;
  }
  return hex;
}

/// Why a state-changing request is refused (empty when it may proceed): it must carry the launch token in
/// kTokenHeader, come from the page's own origin when the browser names one, and send JSON. A web page of another
/// origin can send none of these without a CORS preflight this server never grants.
std::string refusal(const httplib::Request& req, const std::string& token) {
  if (req.get_header_value(kTokenHeader) != token)
    return "missing or wrong " + std::string(kTokenHeader) + ": use the page at the URL silva view printed";
  const std::string origin = req.get_header_value("Origin");
  if (!origin.empty() && origin != "http://" + req.get_header_value("Host")) return "cross-origin request refused";
  if (req.get_header_value("Content-Type").rfind("application/json", 0) != 0) return "the body must be application/json";
  return {};
}

/// `route` behind the in-flight cap `counter` / `max_in_flight`, translated to httplib; with a `token`, only
/// requests that pass refusal() reach it (403 otherwise).
httplib::Server::Handler bounded_handler(Route route, std::atomic<int>& counter, int max_in_flight,
                                         const std::string* token) {
  return [route = std::move(route), &counter, max_in_flight, token](const httplib::Request& req,
                                                                   httplib::Response& res) {
    set_common_headers(res);
    if (token != nullptr) {
      const std::string why = refusal(req, *token);
      if (!why.empty()) {
        res.status = 403;
        res.set_content("{\"error\":\"" + why + "\"}", "application/json");  // why holds no quote or backslash
        return;
      }
    }
    if (++counter > max_in_flight) {
      --counter;
      res.status = 503;
      res.set_header("Retry-After", "1");
      res.set_content("{\"error\":\"busy: request dropped\"}", "application/json");
      return;
    }
    const Release release{counter};
    Request r;
    for (const auto& [k, v] : req.params) r.params[k] = v;
    r.body = req.body;
    Reply reply;
    try {
      reply = route(r);
    } catch (const std::exception& e) {
      reply = Reply{500, "text/plain", std::string("internal error: ") + e.what() + "\n", {}};
    }
    res.status = reply.status;
    for (const auto& [k, v] : reply.headers) res.set_header(k, v);
    res.set_content(reply.body, reply.content_type);
  };
}

}  // namespace

ViewServer::ViewServer(const fs::path& page_dir)
    : server_(std::make_unique<httplib::Server>()), token_(random_token()) {
  server_->new_task_queue = [] { return new httplib::ThreadPool(kServerThreads); };
  server_->set_read_timeout(kReadTimeoutSeconds, 0);
  server_->set_write_timeout(kReadTimeoutSeconds, 0);
  server_->set_keep_alive_max_count(1);  // one request per connection: a slow client cannot keep its thread
  server_->set_payload_max_length(kMaxBodyBytes);
  for (const char* name : kPageFiles) {
    const fs::path file = page_dir / name;
    std::string path = "/";
    if (std::string_view(name) != "index.html") path.append(name);
    server_->Get(path, [text = read_page_file(file), type = mime_type(file)](const httplib::Request&,
                                                                               httplib::Response& res) {
      set_common_headers(res);
      res.set_content(text, type);
    });
  }
  server_->set_error_handler([](const httplib::Request&, httplib::Response& res) {
    set_common_headers(res);
    if (res.body.empty()) res.set_content(res.status == 404 ? "not found\n" : "error\n", "text/plain");
  });
}

ViewServer::~ViewServer() = default;

std::atomic<int>& ViewServer::new_counter() {
  in_flight_.push_back(std::make_unique<std::atomic<int>>(0));
  return *in_flight_.back();
}

void ViewServer::get(const std::string& path, Route route, int max_in_flight) {
  server_->Get(path, bounded_handler(std::move(route), new_counter(), max_in_flight, nullptr));
}

void ViewServer::post(const std::string& path, Route route, int max_in_flight) {
  server_->Post(path, bounded_handler(std::move(route), new_counter(), max_in_flight, &token_));
}

int ViewServer::bind(const std::string& host, int port) {
  const int bound = port == 0 ? server_->bind_to_any_port(host) : (server_->bind_to_port(host, port) ? port : -1);
  if (bound <= 0) throw std::runtime_error("cannot listen on " + host + ":" + std::to_string(port));
  return bound;
}

void ViewServer::run() { server_->listen_after_bind(); }

void ViewServer::stop() { server_->stop(); }

}  // namespace silva::web

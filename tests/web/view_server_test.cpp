// The view's HTTP server: only its page and routes are served, and a route's cap answers 503 at once.
#include <gtest/gtest.h>
#include <httplib.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <future>
#include <thread>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <vector>

#include "tests/common/scratch_dirs.hpp"
#include "web/view_server.hpp"

namespace silva::web {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

/// A fresh scratch folder named `name`, removed when every test passed.
fs::path scratch_dir(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / ("silva_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  test::remove_when_passed(dir);
  return dir;
}

/// A page folder with the three page files, each holding its own name.
fs::path page_dir() {
  const fs::path dir = scratch_dir("view_server_page");
  for (const char* name : kPageFiles) std::ofstream(dir / name) << "page file " << name;
  return dir;
}

/// A server on a free port of 127.0.0.1, running on its own thread until destroyed.
struct RunningServer {
  ViewServer server;
  int port = 0;
  std::thread thread;
  explicit RunningServer(const fs::path& dir) : server(dir) {}
  void start() {
    port = server.bind("127.0.0.1", 0);
    thread = std::thread([this] { server.run(); });
  }
  ~RunningServer() {
    server.stop();
    if (thread.joinable()) thread.join();
  }
};

TEST(ViewServer, ServesThePageAndRoutesOnly) {
  RunningServer s(page_dir());
  s.server.get("/answer", [](const Request& r) { return Reply{200, "text/plain", "x=" + r.params.at("x"), {}}; });
  s.start();
  httplib::Client client("127.0.0.1", s.port);
  const auto index = client.Get("/");
  ASSERT_TRUE(index);
  EXPECT_EQ(index->status, 200);
  EXPECT_EQ(index->body, "page file index.html");
  EXPECT_NE(index->get_header_value("Content-Security-Policy").find("default-src 'self'"), std::string::npos);
  EXPECT_EQ(client.Get("/view.js")->body, "page file view.js");
  EXPECT_EQ(client.Get("/answer?x=7")->body, "x=7");
  for (const char* path : {"/index.html.bak", "/../view.js", "/etc/passwd", "/answer/more"})
    EXPECT_EQ(client.Get(path)->status, 404) << path;
}

TEST(ViewServer, MissingPageFileIsNamed) {
  const fs::path dir = scratch_dir("view_server_empty");
  try {
    ViewServer server(dir);
    FAIL() << "no error for a missing page";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("index.html"), std::string::npos) << e.what();
  }
}

TEST(ViewServer, BusyRouteDropsRequestsInsteadOfQueueing) {
  RunningServer s(page_dir());
  std::promise<void> release;
  std::shared_future<void> released = release.get_future().share();
  std::atomic<int> entered{0};
  s.server.get("/slow", [&](const Request&) {
    ++entered;
    released.wait();
    return Reply{200, "text/plain", "done", {}};
  }, 1);
  s.start();
  auto first = std::async(std::launch::async, [&] { return httplib::Client("127.0.0.1", s.port).Get("/slow")->status; });
  for (int i = 0; i < 200 && entered == 0; ++i) std::this_thread::sleep_for(10ms);
  ASSERT_EQ(entered, 1);
  const auto second = httplib::Client("127.0.0.1", s.port).Get("/slow");
  ASSERT_TRUE(second);
  EXPECT_EQ(second->status, 503);
  EXPECT_EQ(second->get_header_value("Retry-After"), "1");
  release.set_value();
  EXPECT_EQ(first.get(), 200);
  EXPECT_EQ(entered, 1) << "the dropped request must not run the route";
}

TEST(ViewServer, ClientsTricklingHeadersDoNotHoldUpOthers) {
  RunningServer s(page_dir());
  s.server.get("/state", [](const Request&) { return Reply{200, "text/plain", "ok", {}}; });
  s.start();
  // Eight connections that send half a request line and then a byte at a time, slower than any client would.
  std::vector<int> slow;
  for (int i = 0; i < 8; ++i) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(uint16_t(s.port));
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ASSERT_EQ(::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
    ASSERT_EQ(::send(fd, "GET /sta", 8, 0), 8);
    slow.push_back(fd);
  }
  std::this_thread::sleep_for(200ms);
  for (int fd : slow) ::send(fd, "t", 1, 0);
  httplib::Client client("127.0.0.1", s.port);
  client.set_read_timeout(1, 0);  // shorter than kReadTimeoutSeconds: the slow clients must not be waited for
  const auto r = client.Get("/state");
  ASSERT_TRUE(r) << "a trickling client held up /state";
  EXPECT_EQ(r->body, "ok");
  for (int fd : slow) ::close(fd);
}

TEST(ViewServer, AThrowingRouteAnswers500) {
  RunningServer s(page_dir());
  s.server.post("/boom", [](const Request&) -> Reply { throw std::runtime_error("kaput"); });
  s.start();
  const auto r = httplib::Client("127.0.0.1", s.port)
                     .Post("/boom", {{kTokenHeader, s.server.token()}}, "{}", "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 500);
  EXPECT_NE(r->body.find("kaput"), std::string::npos);
}

TEST(ViewServer, StateChangingRequestsNeedTheTokenTheSameOriginAndJson) {
  RunningServer s(page_dir());
  std::atomic<int> reached{0};
  s.server.post("/config", [&](const Request&) {
    ++reached;
    return Reply{};
  });
  s.start();
  const std::string& token = s.server.token();
  EXPECT_EQ(token.size(), 32u);
  EXPECT_NE(token, ViewServer(page_dir()).token());  // drawn per launch
  httplib::Client c("127.0.0.1", s.port);
  const std::string self = "http://127.0.0.1:" + std::to_string(s.port);
  const auto status = [&](const httplib::Headers& headers, const std::string& type) {
    const auto r = c.Post("/config", headers, "{\"seed\": \"1\"}", type);
    return r ? r->status : -1;
  };
  // What a page of another origin can send without a preflight: no custom header, a simple content type.
  EXPECT_EQ(status({}, "text/plain"), 403);
  EXPECT_EQ(status({{"Origin", "http://evil.example"}}, "application/json"), 403);
  EXPECT_EQ(status({{kTokenHeader, "0123456789abcdef0123456789abcdef"}}, "application/json"), 403);
  EXPECT_EQ(status({{kTokenHeader, token}, {"Origin", "http://evil.example"}}, "application/json"), 403);
  EXPECT_EQ(status({{kTokenHeader, token}}, "text/plain"), 403);
  EXPECT_EQ(reached.load(), 0);
  EXPECT_EQ(status({{kTokenHeader, token}}, "application/json"), 200);
  EXPECT_EQ(status({{kTokenHeader, token}, {"Origin", self}}, "application/json; charset=utf-8"), 200);
  EXPECT_EQ(reached.load(), 2);
}

}  // namespace
}  // namespace silva::web

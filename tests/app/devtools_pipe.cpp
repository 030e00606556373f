#include "devtools_pipe.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <stdexcept>
#include <thread>
#include <vector>

namespace silva::test {

namespace fs = std::filesystem;

std::optional<fs::path> find_chromium() {
  if (const char* env = std::getenv("SILVA_CHROMIUM"); env && *env) {
    if (fs::exists(env)) return fs::path(env);
    return std::nullopt;
  }
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin";
  size_t start = 0;
  while (start <= dirs.size()) {
    const size_t end = std::min(dirs.find(':', start), dirs.size());
    for (const char* name : {"chromium", "chromium-browser"}) {
      const fs::path candidate = fs::path(dirs.substr(start, end - start)) / name;
      if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    start = end + 1;
  }
  return std::nullopt;
}

DevtoolsBrowser::DevtoolsBrowser(const fs::path& chromium, const fs::path& scratch, const std::string& url) {
  int in[2], out[2];  // in: we write, Chromium reads fd 3; out: Chromium writes fd 4, we read
  if (::pipe(in) != 0 || ::pipe(out) != 0) throw std::runtime_error("pipe() failed");
  const std::string profile = "--user-data-dir=" + (scratch / "chromium-profile").string();
  std::vector<std::string> args = {chromium.string(), "--headless=new", "--remote-debugging-pipe", "--no-sandbox",
                                   "--disable-gpu", "--no-first-run", "--no-default-browser-check",
                                   "--disable-extensions", "--window-size=1280,720", profile, "about:blank"};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_ = ::fork();
  if (pid_ == 0) {
    ::dup2(in[0], 3);
    ::dup2(out[1], 4);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
    ::execv(argv[0], argv.data());
    _exit(127);
  }
  ::close(in[0]);
  ::close(out[1]);
  to_browser_ = in[1];
  from_browser_ = out[0];
  const std::string target = call("Target.createTarget", {{"url", url}}, true)["targetId"];
  session_ = call("Target.attachToTarget", {{"targetId", target}, {"flatten", true}}, true)["sessionId"];
  call("Runtime.enable");
  call("Emulation.setFocusEmulationEnabled", {{"enabled", true}});
}

DevtoolsBrowser::~DevtoolsBrowser() {
  try {
    call("Browser.close", nlohmann::json::object(), true);
  } catch (const std::exception&) {
    ::kill(pid_, SIGKILL);
  }
  ::close(to_browser_);
  ::close(from_browser_);
  int status = 0;
  ::waitpid(pid_, &status, 0);
}

std::string DevtoolsBrowser::read_message(int timeout_ms) {
  for (;;) {
    const size_t nul = buffer_.find('\0');
    if (nul != std::string::npos) {
      std::string message = buffer_.substr(0, nul);
      buffer_.erase(0, nul + 1);
      return message;
    }
    pollfd p{from_browser_, POLLIN, 0};
    if (::poll(&p, 1, timeout_ms) <= 0) return {};
    char chunk[65536];
    const ssize_t n = ::read(from_browser_, chunk, sizeof chunk);
    if (n <= 0) return {};
    buffer_.append(chunk, size_t(n));
  }
}

nlohmann::json DevtoolsBrowser::call(const std::string& method, const nlohmann::json& params, bool to_browser) {
  const int id = next_id_++;
  nlohmann::json message = {{"id", id}, {"method", method}, {"params", params}};
  if (!to_browser) message["sessionId"] = session_;
  const std::string text = message.dump() + std::string(1, '\0');
  if (::write(to_browser_, text.data(), text.size()) != ssize_t(text.size()))
    throw std::runtime_error("DevTools pipe: write failed (" + method + ")");
  for (;;) {
    const std::string reply = read_message(30000);
    if (reply.empty()) throw std::runtime_error("DevTools pipe: no answer to " + method);
    const nlohmann::json j = nlohmann::json::parse(reply, nullptr, false);
    if (!j.is_object() || !j.contains("id") || j["id"] != id) continue;  // an event, or another answer
    if (j.contains("error")) throw std::runtime_error("DevTools: " + method + ": " + j["error"].dump());
    return j.value("result", nlohmann::json::object());
  }
}

nlohmann::json DevtoolsBrowser::eval(const std::string& expression) {
  const nlohmann::json r =
      call("Runtime.evaluate", {{"expression", expression}, {"awaitPromise", true}, {"returnByValue", true}});
  if (r.contains("exceptionDetails")) throw std::runtime_error("page: " + expression + ": " + r["exceptionDetails"].dump());
  return r["result"].value("value", nlohmann::json());
}

bool DevtoolsBrowser::wait_for(const std::string& expression, std::chrono::milliseconds timeout) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < end) {
    if (eval("!!(" + expression + ")") == true) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

void DevtoolsBrowser::hold_key(char key, std::chrono::milliseconds hold) {
  const std::string k(1, key);
  const std::string code = std::string("Key") + char(std::toupper(key));
  const int vk = std::toupper(key);
  call("Input.dispatchKeyEvent", {{"type", "keyDown"}, {"key", k}, {"code", code}, {"windowsVirtualKeyCode", vk}});
  std::this_thread::sleep_for(hold);
  call("Input.dispatchKeyEvent", {{"type", "keyUp"}, {"key", k}, {"code", code}, {"windowsVirtualKeyCode", vk}});
}

}  // namespace silva::test

// `silva view` in a real browser: headless Chromium over its DevTools pipe loads the page, moves,
// switches to the semantic view, changes the seed, captures, and sends a bad config value.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <regex>
#include <thread>

#include "devtools_pipe.hpp"
#include "silva_process.hpp"

namespace silva::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

/// A small, fast world (the tiny run's) rendered with every output type.
std::vector<std::string> world_args() {
  return {"--set", "output.resolution=64x48", "--set", "world.extent=128", "--set", "world.render_distance=48",
          "--set", "trail.control_points=6", "--set", "camera.far=40", "--set", std::string("output.types=") + kAllTypes};
}

/// The URL `silva view` printed on stdout ("" when none came within 60 s or the process ended).
std::string wait_for_url(const ChildProcess& view) {
  const std::regex url(R"(http://127\.0\.0\.1:([0-9]+)/\?token=[0-9a-f]{32})");
  for (int i = 0; i < 600; ++i) {
    std::smatch m;
    const std::string out = read_file(view.out);
    if (std::regex_search(out, m, url)) return m[0].str();
    if (::waitpid(view.pid, nullptr, WNOHANG) == view.pid) return {};
    std::this_thread::sleep_for(100ms);
  }
  return {};
}

/// A hash of the canvas's pixels.
constexpr const char* kCanvasHash =
    "(() => { const d = document.getElementById('view').getContext('2d').getImageData(0, 0, 960, 540).data;"
    " let h = 7; for (let i = 0; i < d.length; i += 3) h = (h * 31 + d[i]) | 0; return h; })()";

/// True once a full-resolution frame of the current pose and view is on the canvas.
constexpr const char* kStill = "window.silva && silva.still && silva.fullFrames > 0";

TEST(ViewBrowser, ExploreCaptureAndReportErrors) {
  const std::optional<fs::path> chromium = find_chromium();
  if (!chromium) GTEST_SKIP() << "no Chromium installed (apt install chromium, or set SILVA_CHROMIUM): the browser test is skipped";
  const fs::path dir = fresh_test_dir();
  const fs::path view_out = dir / "view-out";
  std::vector<std::string> args = {"view", "--port", "0", "--seed", "11", "--set", "output.dir=" + view_out.string()};
  const std::vector<std::string> world = world_args();
  args.insert(args.end(), world.begin(), world.end());
  const ChildProcess view = start_silva(args, dir);
  const std::string url = wait_for_url(view);
  ASSERT_FALSE(url.empty()) << "silva view printed no URL; stderr:\n" << read_file(view.err);

  {
    DevtoolsBrowser browser(*chromium, dir, url);
    ASSERT_TRUE(browser.wait_for(kStill, 60s)) << "no full frame on the canvas";
    const nlohmann::json start_hash = browser.eval(kCanvasHash);
    const nlohmann::json start_pose = browser.eval("silva.pose");

    // Move: hold W on the focused canvas.
    browser.eval("document.getElementById('view').focus()");
    browser.hold_key('w', 600ms);
    ASSERT_TRUE(browser.wait_for(kStill, 30s));
    const nlohmann::json moved_pose = browser.eval("silva.pose");
    EXPECT_NE(moved_pose["x"], start_pose["x"]) << "W did not move the camera";
    const nlohmann::json moved_hash = browser.eval(kCanvasHash);
    EXPECT_NE(moved_hash, start_hash) << "the canvas did not change after moving";

    // The semantic view: only ontology colours on the canvas, and a different picture.
    browser.eval("document.getElementById('view-semantic').click()");
    ASSERT_TRUE(browser.wait_for("silva.view === 'semantic' && " + std::string(kStill), 30s));
    EXPECT_NE(browser.eval(kCanvasHash), moved_hash) << "the semantic view looks like the RGB one";

    // A new seed: the world is rebuilt in the background and the canvas changes.
    const nlohmann::json semantic_hash = browser.eval(kCanvasHash);
    const int generation = browser.eval("silva.generation").get<int>();
    browser.eval("document.getElementById('seed').value = '12'; document.getElementById('apply').click()");
    ASSERT_TRUE(browser.wait_for("silva.generation > " + std::to_string(generation) + " && " + kStill, 60s))
        << "the world of seed 12 never arrived";
    EXPECT_EQ(browser.eval("silva.state.seed"), 12);
    EXPECT_NE(browser.eval(kCanvasHash), semantic_hash) << "the canvas did not change with the seed";

    // Capture, and the files equal a `silva generate` custom capture at the same pose.
    browser.eval("document.getElementById('capture').click()");
    ASSERT_TRUE(browser.wait_for("silva.lastCapture || silva.lastError", 60s));
    ASSERT_EQ(browser.eval("silva.lastError"), "");
    EXPECT_EQ(browser.eval("silva.lastCapture.frame"), 0);
    const fs::path poses = view_out / "0000000012" / "poses.json";
    ASSERT_TRUE(fs::exists(poses));
    std::vector<std::string> gen = {"generate", "--seed", "12", "--out", (dir / "gen-out").string(), "--set",
                                    "captures.sequences=[\"custom\"]", "--set", "captures.poses_file=" + poses.string()};
    gen.insert(gen.end(), world.begin(), world.end());
    const ProcessResult generated = run_silva(gen, dir);
    ASSERT_EQ(generated.code, 0) << generated.err;
    const auto captured = folder_files(view_out / "0000000012" / "custom");
    EXPECT_EQ(captured.size(), 10u) << "camera, instance table and 8 images";
    EXPECT_EQ(file_differences(captured, folder_files(dir / "gen-out" / "0000000012" / "custom")), "");

    // A bad value: the page shows the CLI's message.
    browser.eval("document.getElementById('key').value = 'vegetation.density=99'; "
                 "document.getElementById('apply').click()");
    ASSERT_TRUE(browser.wait_for("silva.lastError !== ''", 10s));
    const ProcessResult cli = run_silva({"validate", "--set", "vegetation.density=99"}, dir);
    ASSERT_EQ(cli.code, 2);
    EXPECT_EQ(browser.eval("silva.lastError").get<std::string>(), lines_of(cli.err).at(0));
  }

  // Ctrl-C stops the server: exit 130.
  ::kill(view.pid, SIGINT);
  const ProcessResult stopped = wait_silva(view);
  EXPECT_EQ(stopped.code, 130) << stopped.err;
}

}  // namespace
}  // namespace silva::test

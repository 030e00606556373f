// The HTTP routes of `silva view` (ViewExplorer::install and the handlers behind them).
#include <cmath>
#include <cstdlib>
#include <string>

#include "app/commands/view/view_explorer.hpp"
#include "pipeline/config/config_print.hpp"
#include "core/error.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {

namespace {

/// Largest streamed frame, pixels per side.
constexpr int kMaxFrameWidth = 3840, kMaxFrameHeight = 2160;

/// A JSON answer.
web::Reply json_reply(const nlohmann::json& body, int status = 200) { return {status, "application/json", body.dump(), {}}; }

/// The error answer: the CLI's line ("silva: error: ...") under "error".
web::Reply error_reply(const std::string& message, int status) {
  return json_reply({{"error", "silva: error: " + message}}, status);
}

/// A finite number parameter, or InputError naming it.
double number_param(const web::Request& r, const std::string& name, double fallback) {
  const auto it = r.params.find(name);
  if (it == r.params.end()) return fallback;
  char* end = nullptr;
  const double v = std::strtod(it->second.c_str(), &end);
  if (it->second.empty() || *end != '\0' || !std::isfinite(v)) throw InputError(name + ": not a number: " + it->second);
  return v;
}

/// A pose from query parameters or a JSON body's fields.
ViewPose pose_of(const nlohmann::json& fields) {
  const auto num = [&](const char* k) {
    if (!fields.contains(k) || !fields[k].is_number()) throw InputError(std::string("capture: ") + k + " must be a number");
    const double v = fields[k].get<double>();
    if (!std::isfinite(v)) throw InputError(std::string("capture: ") + k + " must be finite");
    return v;
  };
  ViewPose p;
  p.position = Vec3d(num("x"), num("y"), num("z"));
  p.yaw_deg = num("yaw");
  p.pitch_deg = std::clamp(num("pitch"), -90.0, 90.0);
  if (fields.contains("walk") && !fields["walk"].is_boolean()) throw InputError("capture: walk must be true or false");
  p.walk = fields.value("walk", false);
  return p;
}

/// Runs `handler`, answering InputError with 400 and IoError with 500, each with the CLI's line.
template <class F>
web::Reply guarded(F&& handler) {
  try {
    return handler();
  } catch (const InputError& e) {
    return error_reply(e.what(), 400);
  } catch (const IoError& e) {
    return error_reply(e.what(), 500);
  }
}

}  // namespace

web::Reply ViewExplorer::frame(const web::Request& r) {
  ViewPose pose;
  pose.position = Vec3d(number_param(r, "x", 0), number_param(r, "y", 0), number_param(r, "z", 0));
  pose.yaw_deg = number_param(r, "yaw", 0);
  pose.pitch_deg = std::clamp(number_param(r, "pitch", 0), -90.0, 90.0);
  pose.walk = number_param(r, "walk", 0) != 0;
  if (r.params.count("fx") && r.params.count("fy"))
    pose.from = Eigen::Vector2d(number_param(r, "fx", 0), number_param(r, "fy", 0));
  const int w = int(number_param(r, "w", 960)), h = int(number_param(r, "h", 540));
  if (w < 16 || h < 16 || w > kMaxFrameWidth || h > kMaxFrameHeight)
    throw InputError("w, h: 16 .. " + std::to_string(kMaxFrameWidth) + " x " + std::to_string(kMaxFrameHeight));
  ViewMode mode = ViewMode::Rgb;
  const auto view = r.params.find("view");
  if (view != r.params.end() && !parse_view_mode(view->second, mode))
    throw InputError("view: " + view->second + "; allowed: rgb, semantic, instance, depth, normal");
  int generation = 0;
  std::shared_ptr<ViewWorld> w_on_screen;
  {
    const std::lock_guard lock(mutex_);
    last_pose_ = pose;
    generation = generation_;
    w_on_screen = world_;
  }
  const ViewFrame f = w_on_screen->render(pose, mode, w, h);
  const nlohmann::json placed = {{"x", f.position.x()}, {"y", f.position.y()}, {"z", f.position.z()},
                                 {"ground", f.ground_z}, {"ms", f.render_ms}, {"schedule_ms", f.schedule_ms},
                                 {"raster_ms", f.raster_ms}, {"shade_ms", f.shade_ms}, {"encode_ms", f.encode_ms},
                                 {"blocked", f.blocked}, {"generation", generation}};
  return {200, "image/jpeg", std::string(f.jpeg.begin(), f.jpeg.end()), {{"X-Silva-Pose", placed.dump()}}};
}

web::Reply ViewExplorer::state() const {
  const std::lock_guard lock(mutex_);
  const Config& c = world_->loaded().config;
  const ViewPose start = world_->start_pose();
  return json_reply({{"seed", c.seed},
                     {"generation", generation_},
                     {"building", building_ || pending_.has_value()},
                     {"error", error_},
                     {"edits", {{"seed", edits_.seed.value_or("")}, {"overrides", edits_.overrides}}},
                     {"start", {{"x", start.position.x()}, {"y", start.position.y()}, {"yaw", start.yaw_deg}}},
                     {"config", config_to_json(world_->loaded())}});
}

web::Reply ViewExplorer::config(const web::Request& r) {
  const nlohmann::json body = nlohmann::json::parse(r.body, nullptr, false);
  if (!body.is_object()) throw InputError("the config request is not a JSON object");
  ViewEdits edits;
  if (body.contains("seed") && body["seed"].is_string() && !body["seed"].get<std::string>().empty())
    edits.seed = body["seed"].get<std::string>();
  if (body.contains("overrides") && body["overrides"].is_array())
    for (const auto& o : body["overrides"])
      if (o.is_string()) edits.overrides.push_back(o.get<std::string>());
  edit(edits);
  return json_reply({{"ok", true}});
}

web::Reply ViewExplorer::capture(const web::Request& r) {
  const nlohmann::json body = nlohmann::json::parse(r.body, nullptr, false);
  if (!body.is_object()) throw InputError("the capture request is not a JSON object");
  return json_reply(world()->capture(pose_of(body)));
}

void ViewExplorer::install(web::ViewServer& server) {
  server.get("/frame", [this](const web::Request& r) { return guarded([&] { return frame(r); }); });
  server.get("/probe", [this](const web::Request& r) {
    return guarded([&] { return json_reply(world()->probe(number_param(r, "u", -1), number_param(r, "v", -1))); });
  }, 4);
  server.get("/state", [this](const web::Request&) { return state(); }, 4);
  server.get("/trail", [this](const web::Request&) { return json_reply(world()->trail(1.0)); });
  server.get("/map", [this](const web::Request&) {
    const auto [png, placement] = world()->class_map();
    return web::Reply{200, "image/png", std::string(png.begin(), png.end()), {{"X-Silva-Map", placement.dump()}}};
  }, 1);
  server.get("/config.toml", [this](const web::Request&) {
    const LoadedConfig& loaded = world()->loaded();
    return web::Reply{200, "application/toml", config_to_toml(loaded),
                      {{"Content-Disposition", "attachment; filename=\"silva-" + std::to_string(loaded.config.seed) +
                                                   ".toml\""}}};
  });
  server.post("/config", [this](const web::Request& r) { return guarded([&] { return config(r); }); });
  server.post("/capture", [this](const web::Request& r) { return guarded([&] { return capture(r); }); }, 1);
}

}  // namespace silva::app

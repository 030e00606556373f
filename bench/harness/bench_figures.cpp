#include "bench/harness/bench_figures.hpp"

#include <fstream>

#include "core/error.hpp"

namespace silva::bench {

std::optional<double> Figure::ratio() const {
  if (!thesis_s || *thesis_s <= 0) return std::nullopt;
  return silva_s / *thesis_s;
}

ThesisTables::ThesisTables(nlohmann::json doc) : doc_(std::move(doc)) {
  if (!doc_.is_object() || !doc_.contains("tables") || !doc_["tables"].is_object())
    throw InputError("thesis tables: expected an object with \"tables\"");
}

ThesisTables ThesisTables::load(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path.string() + ": cannot read the thesis tables (bench/thesis-tables.json)");
  try {
    return ThesisTables(nlohmann::json::parse(in));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path.string() + ": not valid JSON: " + e.what());
  }
}

std::string x_text(const nlohmann::json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_float()) {
    const double d = v.get<double>();
    if (d == double(int64_t(d))) return std::to_string(int64_t(d));
  }
  return v.dump();
}

std::optional<double> ThesisTables::seconds(const std::string& table, const std::string& x) const {
  const auto& tables = doc_["tables"];
  if (!tables.contains(table)) return std::nullopt;
  const auto& t = tables[table];
  if (!t.contains("x") || !t.contains("y")) return std::nullopt;
  const double scale = t.value("unit", "s") == "ms" ? 1e-3 : 1.0;
  for (size_t k = 0; k < t["x"].size() && k < t["y"].size(); ++k)
    if (x_text(t["x"][k]) == x) return t["y"][k].get<double>() * scale;
  return std::nullopt;
}

std::string ThesisTables::title(const std::string& table) const {
  const auto& tables = doc_["tables"];
  return tables.contains(table) ? tables[table].value("title", "") : "";
}

std::vector<std::string> ThesisTables::xs(const std::string& table) const {
  std::vector<std::string> out;
  const auto& tables = doc_["tables"];
  if (tables.contains(table) && tables[table].contains("x"))
    for (const auto& v : tables[table]["x"]) out.push_back(x_text(v));
  return out;
}

double ThesisTables::autopilot_estimate_s() const {
  const auto& tables = doc_["tables"];
  return tables.contains("autopilot") ? tables["autopilot"].value("estimated", 0.0) : 0.0;
}

std::string ThesisTables::machine() const { return doc_.value("machine", ""); }

nlohmann::json figure_json(const Figure& f) {
  const auto ratio = f.ratio();
  return {{"table", f.table},
          {"x", f.x},
          {"silva_s", f.silva_s},
          {"thesis_s", f.thesis_s ? nlohmann::json(*f.thesis_s) : nlohmann::json(nullptr)},
          {"ratio", ratio ? nlohmann::json(*ratio) : nlohmann::json(nullptr)},
          {"extrapolated", f.extrapolated},
          {"note", f.note},
          {"work",
           {{"objects", f.work.objects},
            {"chunks", f.work.chunks},
            {"triangles", f.work.triangles},
            {"frames", f.work.frames},
            {"pixels", f.work.pixels},
            {"bytes", f.work.bytes}}},
          {"breakdown", f.breakdown}};
}

}  // namespace silva::bench

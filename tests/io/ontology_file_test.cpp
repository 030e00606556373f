#include "io/ontology_file.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/error.hpp"

namespace silva::io {
namespace {

void expect_equal(const Ontology& a, const Ontology& b) {
  for (int r = 0; r < kRoleCount; ++r) {
    const OntologyClass &x = a.classes[r], &y = b.classes[r];
    EXPECT_EQ(x.role, y.role);
    EXPECT_EQ(x.id, y.id) << x.role;
    EXPECT_EQ(x.name, y.name) << x.role;
    EXPECT_EQ(x.color, y.color) << x.role;
    EXPECT_EQ(x.rugd, y.rugd) << x.role;
    EXPECT_EQ(x.rellis, y.rellis) << x.role;
    EXPECT_EQ(x.semantic_kitti, y.semantic_kitti) << x.role;
    EXPECT_EQ(x.semantic_kitti_id, y.semantic_kitti_id) << x.role;
  }
}

std::string message_of(const std::string& text) {
  try {
    parse_ontology(text, "my/ontology.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string edited(const std::function<void(nlohmann::json&)>& edit) {
  auto j = nlohmann::json::parse(ontology_json(default_ontology()));
  edit(j);
  return j.dump();
}

TEST(OntologyFile, ShippedFileEqualsCoreDefault) {
  expect_equal(load_ontology(std::string(SILVA_SOURCE_DIR) + "/configs/ontology.json"), default_ontology());
}

TEST(OntologyFile, RoundTripsAndKeepsRoleOrder) {
  Ontology o = default_ontology();
  o.classes[3].id = 3;
  o.classes[4].id = 3;  // several roles may share one id
  o.classes[7].name = "grass & ferns";
  o.classes[7].color = {1, 2, 255};
  const std::string text = ontology_json(o);
  expect_equal(parse_ontology(text, "x"), o);
  EXPECT_EQ(ontology_json(parse_ontology(text, "x")), text);
}

TEST(OntologyFile, AcceptsAnyOrderOfClasses) {
  const std::string text = edited([](nlohmann::json& j) {
    auto& c = j["classes"];
    std::reverse(c.begin(), c.end());
  });
  expect_equal(parse_ontology(text, "x"), default_ontology());
}

TEST(OntologyFile, MissingRoleIsNamed) {
  const std::string m = message_of(edited([](nlohmann::json& j) { j["classes"].erase(5); }));
  EXPECT_NE(m.find("my/ontology.json"), std::string::npos) << m;
  EXPECT_NE(m.find("dead_tree"), std::string::npos) << m;
}

TEST(OntologyFile, DuplicateRoleIsNamed) {
  const std::string m = message_of(edited([](nlohmann::json& j) { j["classes"][2]["role"] = "shrub"; }));
  EXPECT_NE(m.find("shrub"), std::string::npos) << m;
  EXPECT_NE(m.find("more than once"), std::string::npos) << m;
}

TEST(OntologyFile, BadValuesAreRejected) {
  EXPECT_NE(message_of(edited([](nlohmann::json& j) { j["classes"][1]["id"] = 256; })).find("0..255"), std::string::npos);
  EXPECT_NE(message_of(edited([](nlohmann::json& j) { j["classes"][1]["id"] = -1; })).find("classes[1]"), std::string::npos);
  EXPECT_NE(message_of(edited([](nlohmann::json& j) { j["classes"][1]["id"] = 1.5; })), "");
  EXPECT_NE(message_of(edited([](nlohmann::json& j) { j["classes"][1]["color"] = {1, 2}; })).find("color"), std::string::npos);
  EXPECT_NE(message_of(edited([](nlohmann::json& j) { j["classes"][1]["color"] = {1, 2, 300}; })), "");
  EXPECT_NE(message_of(edited([](nlohmann::json& j) { j["classes"][1]["color"] = {1, 2, "3"}; })), "");
  EXPECT_NE(message_of(edited([](nlohmann::json& j) { j["classes"][1]["role"] = "sky"; })).find("allowed"), std::string::npos);
  EXPECT_NE(message_of(edited([](nlohmann::json& j) { j["classes"][1].erase("name"); })).find("name"), std::string::npos);
  EXPECT_NE(message_of(edited([](nlohmann::json& j) { j["classes"] = 3; })), "");
  EXPECT_NE(message_of("[1, 2"), "");
  EXPECT_THROW(load_ontology("/nonexistent/silva/ontology.json"), InputError);
}

}  // namespace
}  // namespace silva::io

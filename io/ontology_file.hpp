#pragma once
/// @file ontology.json (CONTRACT.md): {"classes": [{"role","id","name","color","rugd","rellis"}, ...]}.
#include <filesystem>
#include <string>

#include "core/ontology.hpp"

namespace silva::io {

/// Parses and validates ontology text: each of the ten roles exactly once, ids 0..255, colour
/// three integers 0..255, names and RUGD/RELLIS mappings strings. InputError names `source`.
Ontology parse_ontology(const std::string& text, const std::string& source);

/// Reads and validates an ontology file (see parse_ontology).
Ontology load_ontology(const std::filesystem::path& path);

/// The ontology.json text for `ontology`, classes in role order.
std::string ontology_json(const Ontology& ontology);

}  // namespace silva::io

#include "pipeline/console/reporter.hpp"

#include <iostream>

namespace silva::pipeline {

void Reporter::note(const std::string& line) const {
  if (!flags_.quiet) std::cerr << line << "\n";
}

void Reporter::warn(const std::string& line) const {
  if (!flags_.quiet) std::cerr << "silva: warning: " << line << "\n";
}

void Reporter::result(const nlohmann::json& summary, const std::string& text) const {
  if (flags_.json) {
    std::cout << summary.dump() << "\n";
  } else if (!text.empty()) {
    std::cout << text;
    if (text.back() != '\n') std::cout << "\n";
  }
  std::cout.flush();
}

}  // namespace silva::pipeline

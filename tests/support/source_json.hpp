#pragma once
// A JSON file of the source tree (an example, a robot, a CLI case) for tests that start from one
// and change a few keys.

#include <gtest/gtest.h>

#include <string>

#include "cosserat/io/text_file.hpp"
#include "nlohmann/json.hpp"

namespace cosserat::testing {

/// The file at `relative` (from the source root, e.g. "examples/cantilever.json") parsed; a file
/// that cannot be read fails the test and gives null.
inline nlohmann::json SourceJson(const std::string& relative) {
  std::string text, why;
  if (!io::ReadTextFile(std::string(COSSERAT_SOURCE_DIR) + "/" + relative, &text, &why)) {
    ADD_FAILURE() << relative << ": " << why;
    return nullptr;
  }
  return nlohmann::json::parse(text);
}

}  // namespace cosserat::testing

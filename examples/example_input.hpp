#pragma once
// What the robot examples do first: read `program [problem.json] [output folder]` (with the
// example's defaults), load the problem, and print its errors (one per line) if it has any.
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

#include "cosserat/io/problem.hpp"

struct ExampleInput {
  std::string file;                             ///< the problem file read
  std::filesystem::path dir;                    ///< where the example writes its CSV
  std::optional<cosserat::io::Problem> problem; ///< empty when the file had errors (printed)
};

inline ExampleInput LoadExampleInput(int argc, char** argv, const char* default_file) {
  ExampleInput in{argc > 1 ? argv[1] : default_file, argc > 2 ? argv[2] : "notebooks-data", {}};
  cosserat::io::ParseResult parsed = cosserat::io::LoadProblemFile(in.file);
  for (const auto& e : parsed.errors) std::cerr << e << '\n';
  in.problem = std::move(parsed.problem);
  return in;
}

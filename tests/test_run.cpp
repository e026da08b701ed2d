// run::Run, the entry point the command-line tool and the Python module share: what a Result
// holds, and that the runner follows the problem's analysis and formulation.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "cosserat/io/problem.hpp"
#include "cosserat/run/run.hpp"

namespace cosserat::run {
namespace {

io::Problem Load(const std::string& relative_path) {
  const io::ParseResult r =
      io::LoadProblemFile(std::string(COSSERAT_SOURCE_DIR) + "/" + relative_path);
  EXPECT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors.front());
  return r.problem.value_or(io::Problem());
}

long Lines(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

TEST(Run, ResultHoldsTheDocumentTheNodeTableAndTheSummary) {
  const io::Problem problem = Load("examples/cantilever.json");
  const Result plain = cosserat::run::Run(problem);
  EXPECT_TRUE(plain.converged);
  EXPECT_EQ(plain.json["status"], "converged");
  EXPECT_EQ(plain.json["nodes"]["s"].size(), static_cast<size_t>(problem.nodes));
  EXPECT_TRUE(plain.nodes_csv.empty());  // not asked for
  EXPECT_EQ(plain.log.rfind("cosserat: converged", 0), 0u) << plain.log;
  EXPECT_EQ(Lines(plain.log), 1);

  RunOptions options;
  options.nodes_csv = true;
  const Result with_nodes = cosserat::run::Run(problem, options);
  EXPECT_EQ(with_nodes.nodes_csv.rfind("s,x,y,z,k1,k2,k3\n", 0), 0u);
  EXPECT_EQ(Lines(with_nodes.nodes_csv), problem.nodes + 1);  // the header, one row per node
  EXPECT_EQ(with_nodes.json["tip"], plain.json["tip"]);       // the same solve
}

TEST(Run, FollowsTheFormulation) {
  io::Problem problem = Load("examples/cantilever.json");
  problem.formulation = io::Formulation::kQuaternionFd;
  const Result fd = cosserat::run::Run(problem);
  EXPECT_TRUE(fd.converged);
  EXPECT_NE(fd.log.find("(quaternion-fd)"), std::string::npos) << fd.log;
  problem.analysis = io::Analysis::kModes;
  problem.modes.count = 2;
  const Result modes = cosserat::run::Run(problem);
  EXPECT_EQ(modes.json["modes"]["formulation"], "quaternion-fd");
  EXPECT_EQ(modes.json["modes"]["frequencies_hz"].size(), 2u);
}

}  // namespace
}  // namespace cosserat::run

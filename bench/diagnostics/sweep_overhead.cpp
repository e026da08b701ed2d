// What `cosserat sweep` adds to each point: the time of the study's rows (run::SweepPointRow:
// setting the point's values, validating its problem, running it, collecting the outputs,
// formatting the row) against running the same problems alone (run::Run), over every point,
// twice, interleaved point by point so that both see the same machine:
//   build/bench/diagnostics/sweep_overhead examples/studies/tendon_workspace_1000.json
#include <chrono>
#include <cstdio>

#include "cosserat/io/problem.hpp"
#include "cosserat/io/study.hpp"
#include "cosserat/run/run.hpp"
#include "cosserat/run/sweep.hpp"

int main(int argc, char** argv) {
  using namespace cosserat;
  using Clock = std::chrono::steady_clock;
  if (argc != 2) {
    std::fprintf(stderr, "usage: sweep_overhead STUDY.json\n");
    return 2;
  }
  const io::StudyParseResult parsed = io::LoadStudyFile(argv[1]);
  if (!parsed.study) {
    for (const std::string& e : parsed.errors) std::fprintf(stderr, "%s\n", e.c_str());
    return 2;
  }
  const io::Study& study = *parsed.study;
  for (int round = 0; round < 2; ++round) {
    double alone = 0, row = 0;
    for (std::uint64_t k = 0; k < study.PointCount(); ++k) {
      const io::ParseResult p = io::ParseProblemDocument(study.PointProblem(k));
      auto t0 = Clock::now();
      const run::Result r = run::Run(*p.problem);
      auto t1 = Clock::now();
      const std::string line = run::SweepPointRow(study, k);
      auto t2 = Clock::now();
      alone += std::chrono::duration<double>(t1 - t0).count();
      row += std::chrono::duration<double>(t2 - t1).count();
    }
    std::printf("round %d: %llu points, run alone %.4f s, as study rows %.4f s: the sweep adds "
                "%.1f %%\n",
                round, static_cast<unsigned long long>(study.PointCount()), alone, row,
                100 * (row - alone) / alone);
  }
  return 0;
}

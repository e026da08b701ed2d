// The `cosserat` command:
//   cosserat solve PROBLEM.json [--out RESULT.json] [--csv NODES.csv] [--vtk DIR]
//   cosserat sweep STUDY.json --out RESULTS.csv [--threads N]
//   cosserat validate PROBLEM.json
//   cosserat --version | --help
// Exit codes: 0 converged (or valid), 1 solved but not converged, 2 bad input or usage.

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cosserat/io/json_document.hpp"
#include "cosserat/io/problem.hpp"
#include "cosserat/io/study.hpp"
#include "cosserat/io/text_file.hpp"
#include "cosserat/io/vtk_series.hpp"
#include "cosserat/run/run.hpp"
#include "cosserat/run/sweep.hpp"
#include "output_file.hpp"
#include "sweep_mpi.hpp"

namespace {

constexpr int kExitConverged = 0;
constexpr int kExitNotConverged = 1;
constexpr int kExitBadInput = 2;
// The most threads `sweep --threads` takes (a sweep uses no more threads than points anyway).
constexpr int kMaxThreads = 4096;

const char* const kUsage =
    "usage:\n"
    "  cosserat solve PROBLEM.json [--out RESULT.json] [--csv NODES.csv] [--vtk DIR]\n"
    "  cosserat sweep STUDY.json --out RESULTS.csv [--threads N]   (or under mpirun -np K)\n"
    "  cosserat validate PROBLEM.json\n"
    "  cosserat --version\n"
    "  cosserat --help\n"
    "\n"
    "solve     solve the problem; the result JSON goes to stdout or to --out, the node table\n"
    "          to --csv (statics: s,x,y,z,k1,k2,k3; dynamics: t,node,s,x,y,z for every\n"
    "          recorded frame). A one-line summary is printed on stderr. Dynamics with\n"
    "          --vtk also writes a ParaView time series to DIR: DIR/<problem>.pvd and one\n"
    "          .vtp per recorded frame (positions, directors, strains, internal wrench);\n"
    "          statics, modes and buckling write their equilibrium as one frame at t = 0.\n"
    "sweep     run a study (docs/sweeps.md): its problem at every point of its parameters, one\n"
    "          CSV row per point as it finishes; run again on the same file, it resumes.\n"
    "validate  check the problem (or study) file and print every error found.\n"
    "\n"
    "exit status: 0 converged (or valid), 1 ran but did not converge (the result is still\n"
    "written, its \"status\" says why), 2 bad input or bad usage.\n"
    "The problem format is described in docs/problem-format.md.\n";

struct UsageError {
  std::string message;
};

struct Command {
  std::string name;  // "solve", "validate", "version", "help"
  std::string problem_path;
  std::optional<std::string> out_path;
  std::optional<std::string> csv_path;
  std::optional<std::string> vtk_dir;
  int threads = 0;  // sweep: 0 = all cores
};

/// Takes the value of an option such as `--out FILE` or `--out=FILE`.
std::string OptionValue(const std::vector<std::string>& args, std::size_t* i,
                        const std::string& option) {
  const std::string& arg = args[*i];
  const std::string needs = option + (option == "--vtk"       ? " needs a directory"
                                      : option == "--threads" ? " needs a number of threads"
                                                              : " needs a file name");
  std::string value;
  if (arg.size() > option.size() && arg.compare(0, option.size() + 1, option + "=") == 0)
    value = arg.substr(option.size() + 1);
  else if (*i + 1 < args.size())
    value = args[++*i];
  else
    throw UsageError{needs};
  // An empty name (`--csv=`, `--out ""`) is no file: refused before the run, not after it.
  if (value.empty()) throw UsageError{needs + " (got an empty one)"};
  return value;
}

/// True when both paths name one existing file.
bool SameFile(const std::string& a, const std::string& b) {
  std::error_code ea, eb;
  return std::filesystem::exists(a, ea) && std::filesystem::exists(b, eb) &&
         std::filesystem::equivalent(a, b, ea);
}

/// Where writing to `path` lands: its symbolic links followed (a dangling one too: writing
/// creates its target), its directory made canonical.
std::filesystem::path WriteTarget(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path p = fs::absolute(path, ec);
  for (int hops = 0; hops < 40 && fs::is_symlink(p, ec); ++hops) {
    const fs::path target = fs::read_symlink(p, ec);
    if (ec) break;
    p = target.is_absolute() ? target : p.parent_path() / target;
  }
  return fs::weakly_canonical(p.parent_path(), ec) / p.filename();
}

/// True when both paths name one file, existing or to be written ("o.json", "./o.json", or a
/// link to it).
bool SamePath(const std::string& a, const std::string& b) {
  return SameFile(a, b) || WriteTarget(a) == WriteTarget(b);
}

/// Sets an option that may be given once.
void SetOnce(std::optional<std::string>* value, const std::string& option, std::string given) {
  if (*value) throw UsageError{option + " is given twice ('" + **value + "' and '" + given + "')"};
  *value = std::move(given);
}

Command ParseCommandLine(const std::vector<std::string>& args) {
  if (args.empty()) throw UsageError{"no command given"};
  Command cmd;
  const std::string& first = args[0];
  if (first == "--version" || first == "-V")
    cmd.name = "version";
  else if (first == "--help" || first == "-h" || first == "help")
    cmd.name = "help";
  else if (first == "solve" || first == "validate" || first == "sweep")
    cmd.name = first;
  else
    throw UsageError{"unknown command '" + first + "'"};

  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& arg = args[i];
    const bool is_out = arg == "--out" || arg.rfind("--out=", 0) == 0;
    const bool is_csv = arg == "--csv" || arg.rfind("--csv=", 0) == 0;
    const bool is_vtk = arg == "--vtk" || arg.rfind("--vtk=", 0) == 0;
    if (arg == "--help" || arg == "-h")
      cmd.name = "help";
    else if ((cmd.name == "solve" || cmd.name == "sweep") && is_out)
      SetOnce(&cmd.out_path, "--out", OptionValue(args, &i, "--out"));
    else if (cmd.name == "sweep" && (arg == "--threads" || arg.rfind("--threads=", 0) == 0)) {
      const std::string n = OptionValue(args, &i, "--threads");
      std::size_t used = 0;
      try {
        cmd.threads = std::stoi(n, &used);
      } catch (const std::exception&) {
        cmd.threads = -1;
      }
      if (used != n.size() || cmd.threads < 1 || cmd.threads > kMaxThreads)
        throw UsageError{"--threads needs a whole number from 1 to " + std::to_string(kMaxThreads) +
                         ", got '" + n + "'"};
    }
    else if (cmd.name == "solve" && is_csv)
      SetOnce(&cmd.csv_path, "--csv", OptionValue(args, &i, "--csv"));
    else if (cmd.name == "solve" && is_vtk)
      SetOnce(&cmd.vtk_dir, "--vtk", OptionValue(args, &i, "--vtk"));
    else if (arg.size() > 1 && arg[0] == '-')
      throw UsageError{"unknown option '" + arg + "'"};
    else if (cmd.problem_path.empty())
      cmd.problem_path = arg;
    else
      throw UsageError{"unexpected argument '" + arg + "'"};
  }
  if (cmd.name == "help") return cmd;
  if (cmd.name == "version" && !cmd.problem_path.empty())
    throw UsageError{"--version takes no arguments"};
  if ((cmd.name == "solve" || cmd.name == "validate") && cmd.problem_path.empty())
    throw UsageError{cmd.name + " needs a problem file"};
  if (cmd.name == "sweep" && cmd.problem_path.empty()) throw UsageError{"sweep needs a study file"};
  if (cmd.name == "sweep" && !cmd.out_path) throw UsageError{"sweep needs --out RESULTS.csv"};
  // An output written over the input file would lose it.
  for (const std::optional<std::string>* out : {&cmd.out_path, &cmd.csv_path})
    if (*out && SameFile(**out, cmd.problem_path))
      throw UsageError{"the output '" + **out + "' is the input file; choose another name"};
  if (cmd.out_path && cmd.csv_path && SamePath(*cmd.out_path, *cmd.csv_path))
    throw UsageError{"--out and --csv name the same file '" + *cmd.out_path + "'"};
  return cmd;
}

void PrintLines(const std::vector<std::string>& lines) {
  for (const std::string& line : lines) std::cerr << line << '\n';
}

/// Parses the file and checks that this version can run it; prints the errors if not.
std::optional<cosserat::io::Problem> LoadRunnableProblem(const std::string& path) {
  cosserat::io::ParseResult parsed = cosserat::io::LoadProblemFile(path);
  if (!parsed.ok()) {
    PrintLines(parsed.errors);
    return std::nullopt;
  }
  const std::vector<std::string> unsupported = cosserat::io::UnsupportedFeatures(*parsed.problem);
  if (!unsupported.empty()) {
    PrintLines(unsupported);
    return std::nullopt;
  }
  return std::move(parsed.problem);
}

/// Whether the file is a study ("format": "cosserat-study/1"): validate checks it as one.
bool IsStudyFile(const std::string& path) {
  std::string text, why;
  if (!cosserat::io::ReadTextFile(path, &text, &why)) return false;  // the problem reader says why
  const cosserat::io::detail::JsonDocument doc =
      cosserat::io::detail::ParseJsonDocument(text, path);
  if (!doc.value || !doc.value->is_object()) return false;
  const auto format = doc.value->find("format");
  return format != doc.value->end() && *format == "cosserat-study/1";
}

int RunValidate(const Command& cmd) {
  if (IsStudyFile(cmd.problem_path)) {
    const cosserat::io::StudyParseResult parsed = cosserat::io::LoadStudyFile(cmd.problem_path);
    if (!parsed.study) {
      PrintLines(parsed.errors);
      return kExitBadInput;
    }
    const std::uint64_t n = parsed.study->PointCount();
    std::cout << cmd.problem_path << ": ok (a study of " << n << (n == 1 ? " point" : " points");
    // Points whose values make an invalid problem run as rows with their reason: said here.
    const cosserat::io::StudyPointCheck check =
        cosserat::io::CheckStudyPoints(*parsed.study, 100000);
    if (check.invalid > 0)
      std::cout << "; " << check.invalid << " of the " << (check.checked < n ? "first " : "")
                << check.checked << " are invalid problems, each a row with its reason, the "
                << "first point " << check.first << " ("
                << cosserat::io::PointWords(*parsed.study, check.first)
                << "): " << check.first_error;
    std::cout << ")\n";
    return kExitConverged;
  }
  if (!LoadRunnableProblem(cmd.problem_path)) return kExitBadInput;
  std::cout << cmd.problem_path << ": ok\n";
  return kExitConverged;
}

/// A progress line on stderr for a run longer than about two seconds, when stderr is a terminal
/// (a file or a pipe gets nothing): how far it got (a dynamics run's time, a buckling search's
/// load), the share done, the time left where the run goes to its end (not a buckling search,
/// which stops at the critical load: its time left, read from the share of its maximum, was
/// 4 333 s for a search that ended 2 s later). Redrawn at most four times a second; cleared
/// when the run ends.
class ProgressLine {
 public:
  /// `what` names the quantity ("t" in s, a buckling search's "load", the "modes found" of an
  /// SE(3) modes scan), `unit` its unit. On a terminal the line redraws itself every 0.25 s
  /// from 2 s on; into a file (a batch job's log) it is a plain line every minute.
  ProgressLine(std::string what, std::string unit, bool runs_to_the_end = true)
      : tty_(isatty(STDERR_FILENO) != 0),
        runs_to_the_end_(runs_to_the_end),
        what_(std::move(what)),
        unit_(std::move(unit)),
        start_(Clock::now()),
        last_(start_) {}
  ~ProgressLine() { Clear(); }
  void Clear() {
    if (drawn_ && tty_) std::cerr << "\r\033[K" << std::flush;
    drawn_ = false;
  }
  void operator()(double t, double duration) {
    if (!(duration > 0)) return;
    const auto now = Clock::now();
    const double elapsed = Seconds(now - start_);
    if (tty_ ? elapsed < 2.0 || (drawn_ && Seconds(now - last_) < 0.25)
             : Seconds(now - last_) < 60.0)
      return;
    last_ = now;
    drawn_ = true;
    const double share = std::min(1.0, t / duration);
    std::ostringstream line;
    line << std::setprecision(4) << (tty_ ? "\r" : "") << "cosserat: " << what_ << " " << t
         << " of " << duration << unit_ << " (" << std::fixed << std::setprecision(0)
         << 100 * share << " %), " << std::setprecision(1) << elapsed << " s";
    if (share > 0 && runs_to_the_end_)
      line << ", about " << elapsed * (1 - share) / share << " s left";
    std::cerr << line.str() << (tty_ ? "\033[K" : "\n") << std::flush;
  }

 private:
  using Clock = std::chrono::steady_clock;
  static double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }
  bool tty_, runs_to_the_end_, drawn_ = false;
  std::string what_, unit_;
  Clock::time_point start_, last_;
};

/// The --vtk directory, made before the run, and its series file writable: a bad directory
/// fails fast instead of after the simulation.
void CheckVtkDirectory(const std::string& directory, const std::string& stem) {
  std::error_code ec;
  std::filesystem::create_directories(directory, ec);
  if (ec || !std::filesystem::is_directory(directory, ec))
    throw std::runtime_error(directory + ": cannot create the directory" +
                             (ec ? " (" + ec.message() + ")" : std::string(" (a file is there)")));
  const std::string pvd = (std::filesystem::path(directory) / (stem + ".pvd")).string();
  std::ofstream probe(pvd, std::ios::app);
  if (!probe)
    throw std::runtime_error("cannot write '" + pvd + "' (" + std::strerror(errno) + ")");
}

int RunSolve(const Command& cmd) {
  const std::optional<cosserat::io::Problem> problem = LoadRunnableProblem(cmd.problem_path);
  if (!problem) return kExitBadInput;
  // The outputs replace their targets only when the result is written (OutputFile): a refused,
  // failed or killed run leaves the last result in place.
  if (cmd.vtk_dir && problem->has_assembly &&
      problem->analysis != cosserat::io::Analysis::kDynamics)
    throw UsageError{"--vtk writes an assembly's dynamics frames; this assembly's analysis is \"" +
                     cosserat::io::ToString(problem->analysis) + "\""};
  const std::string stem = std::filesystem::path(cmd.problem_path).stem().string();
  if (cmd.vtk_dir) CheckVtkDirectory(*cmd.vtk_dir, stem);
  std::optional<cosserat::apps::OutputFile> out_file, csv_file;
  if (cmd.out_path) out_file.emplace(*cmd.out_path);
  if (cmd.csv_path) csv_file.emplace(*cmd.csv_path);
  std::ostream& out = out_file ? static_cast<std::ostream&>(out_file->stream()) : std::cout;

  cosserat::run::RunOptions options;
  options.nodes_csv = csv_file.has_value();
  options.frames = cmd.vtk_dir.has_value();
  cosserat::run::Result result;
  {
    const bool dynamics = problem->analysis == cosserat::io::Analysis::kDynamics;
    const bool modes = problem->analysis == cosserat::io::Analysis::kModes;
    ProgressLine progress(dynamics ? "t =" : modes ? "modes found" : "load", dynamics ? " s" : "",
                          dynamics || modes);
    options.progress = [&progress](double t, double duration) { progress(t, duration); };
    result = cosserat::run::Run(*problem, options);
  }
  out << result.json.dump(2) << '\n';
  if (csv_file) csv_file->stream() << result.nodes_csv;
  std::cerr << result.log;
  if (cmd.vtk_dir) {
    std::string error;
    if (!cosserat::io::WriteVtkSeries(*cmd.vtk_dir, stem, result.frames, result.node_radius,
                                      &error))
      throw std::runtime_error(error);
    std::cerr << "cosserat: " << result.frames.size()
              << (result.frames.size() == 1 ? " frame" : " frames") << " written to "
              << (std::filesystem::path(*cmd.vtk_dir) / (stem + ".pvd")).string() << '\n';
  }
  if (out_file) out_file->Commit();
  if (csv_file) csv_file->Commit();
  std::cout.flush();
  if (!out_file && !std::cout) throw std::runtime_error("writing the result failed");
  return result.converged ? kExitConverged : kExitNotConverged;
}

int RunSweep(const Command& cmd) {
  const cosserat::io::StudyParseResult parsed = cosserat::io::LoadStudyFile(cmd.problem_path);
  if (!parsed.study) {
    // Every MPI rank reads the file; one says what is wrong with it (each exits 2).
    if (cosserat::apps::LaunchedRank() == 0) PrintLines(parsed.errors);
    return kExitBadInput;
  }
  cosserat::run::SweepOptions options;
  options.threads = cmd.threads > 0
                        ? cmd.threads
                        : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  ProgressLine progress("point", "");
  options.progress = [&progress](std::uint64_t done, std::uint64_t total) {
    progress(static_cast<double>(done), static_cast<double>(total));
  };
  const int ranks = cosserat::apps::LaunchedRanks();
  if (ranks > 1 && !cosserat::apps::HaveMpi())
    throw std::runtime_error("started by mpirun with " + std::to_string(ranks) +
                             " ranks, but this build has no MPI: every rank would run the whole "
                             "study (install libopenmpi-dev and build again)");
  int tasks = 1;
  if (cosserat::apps::UnjoinedSlurmTasks(&tasks))
    throw std::runtime_error(
        "srun started this sweep as task " + std::string(std::getenv("SLURM_PROCID") ?
        std::getenv("SLURM_PROCID") : "?") + " of " + std::to_string(tasks) + ", but no MPI "
        "environment joins the tasks: each would run the whole study into " + *cmd.out_path +
        " (start it with srun --mpi=pmix or pmi2, or mpirun; or one task with --threads)");
  bool root = true;
  int joined = ranks;  // the ranks MPI joined
  const cosserat::run::SweepSummary s =
      ranks > 1 ? cosserat::apps::RunSweepMpi(*parsed.study, *cmd.out_path,
                                              cmd.threads > 0 ? cmd.threads : 1, options.progress,
                                              &root, &joined)
                : cosserat::run::RunSweep(*parsed.study, *cmd.out_path, options);
  progress.Clear();
  if (!root) return kExitConverged;  // rank 0 reports and exits with the study's status
  std::cerr << "cosserat: sweep " << (s.complete ? "complete" : "incomplete") << ", " << s.points
            << (s.points == 1 ? " point (" : " points (") << s.resumed << " from the file, "
            << s.ran << " run now on ";
  if (ranks > 1)
    std::cerr << joined << (joined == 1 ? " MPI rank" : " MPI ranks");
  else
    std::cerr << options.threads << (options.threads == 1 ? " thread" : " threads");
  std::cerr << "), " << s.failed << " not converged, " << std::setprecision(3) << s.wall_time_s
            << " s; rows in " << *cmd.out_path << '\n';
  if (s.dropped > 0)
    std::cerr << "cosserat: warning: " << s.dropped << (s.dropped == 1 ? " line" : " lines")
              << " of " << *cmd.out_path << " held no row of this study (no point index in "
              << "front, an index past its " << s.points << " points, or a point's second row) "
              << "and " << (s.dropped == 1 ? "was" : "were") << " dropped on resume\n";
  for (const std::string& output : s.empty_outputs)
    std::cerr << "cosserat: warning: output " << output
              << " is empty in every converged point: does the pointer name a field of the "
                 "result (docs/problem-format.md, \"Result\")?\n";
  return s.complete && s.failed == 0 ? kExitConverged : kExitNotConverged;
}

int Run(const std::vector<std::string>& args) {
  const Command cmd = ParseCommandLine(args);
  if (cmd.name == "help") {
    std::cout << kUsage;
    return 0;
  }
  if (cmd.name == "version") {
    std::cout << "cosserat " << COSSERAT_VERSION_STRING << '\n';
    return 0;
  }
  if (cmd.name == "validate") return RunValidate(cmd);
  if (cmd.name == "sweep") return RunSweep(cmd);
  return RunSolve(cmd);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return Run(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const UsageError& e) {
    std::cerr << "cosserat: " << e.message << "\n\n" << kUsage;
  } catch (const std::exception& e) {
    std::cerr << "cosserat: error: " << e.what() << '\n';
  } catch (...) {
    std::cerr << "cosserat: error: unexpected failure\n";
  }
  return kExitBadInput;
}

#include "cosserat/run/sweep.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "cosserat/io/json_reader.hpp"
#include "cosserat/io/problem.hpp"
#include "cosserat/numerics/thread_team.hpp"
#include "cosserat/run/run.hpp"

namespace cosserat::run {
namespace {

using json = nlohmann::json;

using io::detail::ShortestNumber;  // a CSV number: reads back as the double, in fewest digits

/// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string Field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return out + "\"";
}

std::string OutputField(const nlohmann::ordered_json& result, const std::string& pointer) {
  const nlohmann::ordered_json::json_pointer p(pointer);
  if (!result.contains(p)) return "";
  const nlohmann::ordered_json& v = result[p];
  if (v.is_number()) return ShortestNumber(v.get<double>());
  if (v.is_string()) return Field(v.get<std::string>());
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_null()) return "nan";  // JSON's null: no number, or one JSON cannot hold (NaN, inf)
  return Field(v.dump());
}

/// Where field `column` (0-based) of a CSV row starts: commas inside a quoted field (an output
/// that is an array or an object, written as its JSON text) do not separate fields.
std::size_t StartOfField(const std::string& line, std::size_t column) {
  bool quoted = false;
  std::size_t field = 0;
  for (std::size_t i = 0; i < line.size() && field < column; ++i) {
    if (line[i] == '"') quoted = !quoted;  // a doubled quote toggles twice
    else if (line[i] == ',' && !quoted && ++field == column) return i + 1;
  }
  return field == column ? 0 : line.size();
}

}  // namespace

std::string SweepPointRow(const io::Study& study, std::uint64_t k) {
  const auto t0 = std::chrono::steady_clock::now();
  std::ostringstream row;
  row << k;
  for (double v : study.Point(k)) row << ',' << ShortestNumber(v);
  std::string status;
  nlohmann::ordered_json result;
  try {
    const io::ParseResult parsed = io::ParseProblemDocument(study.PointProblem(k));
    if (!parsed.ok()) {
      status = "invalid: " + parsed.errors.front();
    } else {
      const std::vector<std::string> unsupported = io::UnsupportedFeatures(*parsed.problem);
      if (!unsupported.empty()) {
        status = "unsupported: " + unsupported.front();
      } else {
        Result r = Run(*parsed.problem);
        result = std::move(r.json);
        status = result.value("status", std::string("unknown"));
      }
    }
  } catch (const std::exception& e) {
    status = std::string("error: ") + e.what();
  }
  for (const io::StudyOutput& o : study.outputs) row << ',' << OutputField(result, o.path);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  row << ',' << Field(status) << ',' << ShortestNumber(wall);
  return row.str();
}

namespace {

/// A CSV line's fields as written (quotes kept; a comma inside quotes does not separate).
std::vector<std::string> HeaderFields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    if (c == ',' && !quoted)
      fields.emplace_back();
    else if (c != '\r')
      fields.back() += c;
  }
  return fields;
}

/// Where a file's header line first differs from the study's, column by column.
std::string HeaderDifference(const std::string& found, const std::string& wanted) {
  const std::vector<std::string> a = HeaderFields(found), b = HeaderFields(wanted);
  for (std::size_t i = 0; i < std::max(a.size(), b.size()); ++i) {
    if (i < a.size() && i < b.size() && a[i] == b[i]) continue;
    return "column " + std::to_string(i + 1) + " is " + (i < a.size() ? a[i] : "missing") +
           ", this study's " + (i < b.size() ? b[i] : "none");
  }
  return "it differs in its line ending";
}

/// The rows already in the file (whole lines after the study's header), by point index;
/// *dropped counts the whole lines that are not (SweepSummary::dropped).
std::map<std::uint64_t, std::string> ReadRows(const std::string& path, const std::string& header,
                                              std::uint64_t points, std::uint64_t* dropped) {
  std::map<std::uint64_t, std::string> rows;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return rows;
  // A directory, a device (/dev/full reads zeros without end) or a FIFO holds no results.
  if (!std::filesystem::is_regular_file(path, ec))
    throw std::runtime_error(path + ": not a regular file (the results are a CSV file)");
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error(path + ": cannot read the file (" + std::strerror(errno) + ")");
  std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (text.empty()) return rows;
  std::size_t end = text.find('\n');
  if (end == std::string::npos || text.substr(0, end) != header)
    throw std::runtime_error(path + ": its header is not this study's (" +
                             HeaderDifference(text.substr(0, end), header) +
                             "; another study's results?)");
  for (std::size_t start = end + 1; start < text.size(); start = end + 1) {
    end = text.find('\n', start);
    if (end == std::string::npos) break;  // a torn last line: the point runs again
    const std::string line = text.substr(start, end - start);
    std::size_t used = 0;
    bool row = false;
    try {
      const unsigned long long k = std::stoull(line, &used);
      row = used > 0 && used < line.size() && line[used] == ',' && k < points;
      if (row && !rows.emplace(k, line).second) {
        rows[k] = line;  // the later row of a point is its latest
        row = false;
      }
    } catch (const std::exception&) {
      // not a row
    }
    if (!row) ++*dropped;
  }
  return rows;
}

/// Writes what `write` puts out to `path` through a temporary file and a rename, so that the
/// file is whole at every moment.
template <typename Write>
void WriteWhole(const std::string& path, const Write& write) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f)  // named as the file asked for: the temporary beside it is the tool's own
      throw std::runtime_error(path + ": cannot write (" + std::strerror(errno) + ")");
    write(f);
    if (!f) throw std::runtime_error(path + ": cannot write");
  }
  std::filesystem::rename(tmp, path);
}

/// Each resumed row's parameter values must be this study's at its point: a file of another
/// study with the same columns (another grid, other draws) is refused, not mixed in.
void CheckResumedPoints(const std::string& path, const io::Study& study,
                        const std::map<std::uint64_t, std::string>& rows) {
  for (const auto& [k, line] : rows) {
    const std::vector<double> point = study.Point(k);
    for (std::size_t j = 0; j < point.size(); ++j) {
      const std::size_t start = StartOfField(line, j + 1);
      const std::size_t end = std::min(line.find(',', start), line.size());
      // By value: a file written with more digits than needed (%.17g) is the same point, and so
      // is one a few ulps off (grids before they followed numpy.linspace wrote 0.9999999999999998
      // where it gives 1).
      const std::string found = line.substr(start, end - start);
      const std::string wanted = ShortestNumber(point[j]);
      char* parsed_end = nullptr;
      const double value = std::strtod(found.c_str(), &parsed_end);
      const double ulps = 4.0 * std::numeric_limits<double>::epsilon() *
                          std::max(std::abs(value), std::abs(point[j]));
      if (parsed_end != found.c_str() + found.size() || found.empty() ||
          !(std::abs(value - point[j]) <= ulps))
        throw std::runtime_error(path + ": its row of point " + std::to_string(k) + " has " +
                                 study.parameters[j].path + " = " + found +
                                 ", this study's point has " + wanted +
                                 " (another study's results? remove the file or name another "
                                 "--out)");
    }
  }
}

/// A record kept beside the CSV: its JSON, or a discarded value when it cannot be read.
json ReadRecord(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return f ? json::parse(f, nullptr, false) : json(json::value_t::discarded);
}

/// The problem the rows were computed from, beside the CSV (`<csv>.problem.json`): a resumed
/// study whose base problem changed since (another robot, another load) is refused, naming the
/// first place they differ; so is one whose record is missing, empty or unreadable (rows from an
/// earlier version, or a record removed: their problem is unknown). Neither the description nor
/// the values at the swept paths count (each point sets those).
void CheckAndRecordProblem(const std::string& csv_path, const io::Study& study, bool resuming) {
  const std::string path = csv_path + ".problem.json";
  auto comparable = [&](json doc) {
    if (!doc.is_object()) return doc;
    doc.erase("description");
    for (const io::StudyParameter& p : study.parameters) {
      const json::json_pointer at(p.path);
      if (doc.contains(at)) doc[at] = nullptr;
    }
    return doc;
  };
  if (resuming) {
    const json recorded = ReadRecord(path);
    if (recorded.is_discarded() || !recorded.is_object())
      throw std::runtime_error(csv_path + ": its rows' problem is not recorded (" + path +
                               " is missing or unreadable), so they may be another problem's; "
                               "remove the file or name another --out");
    const json was = comparable(recorded), now = comparable(study.problem);
    if (was != now) {
      const json patch = json::diff(was, now);
      const std::string where =
          patch.empty() ? std::string("/") : patch.front().value("path", std::string("/"));
      throw std::runtime_error(csv_path + ": its rows were computed from another problem (" +
                               path + " differs at " + (where.empty() ? "/" : where) +
                               "); remove both files or name another --out");
    }
  }
  WriteWhole(path, [&](std::ostream& f) { f << study.problem.dump(1) << '\n'; });
}

/// The result fields the columns hold, beside the CSV (`<csv>.outputs.json`, name → JSON
/// pointer): the header names the columns only, so a resumed study whose column now reads
/// another field (tip_x from /tip/position/1) is refused. Rows written before the fields were
/// recorded resume as their header allows (their record is written then); an unreadable record
/// is refused.
void CheckAndRecordOutputs(const std::string& csv_path, const io::Study& study, bool resuming) {
  const std::string path = csv_path + ".outputs.json";
  json now = json::object();
  for (const io::StudyOutput& o : study.outputs) now[o.name] = o.path;
  std::error_code ec;
  if (resuming && std::filesystem::exists(path, ec)) {
    const json was = ReadRecord(path);
    if (was.is_discarded() || !was.is_object())
      throw std::runtime_error(csv_path + ": the record of the result fields its columns hold ("
                               + path + ") is unreadable, so they may be other fields; remove "
                               "the files or name another --out");
    for (const auto& [name, pointer] : now.items())
      if (!was.contains(name) || was[name] != pointer)
        throw std::runtime_error(
            csv_path + ": its column " + name + " holds " +
            (was.contains(name) ? was[name].dump() : std::string("an unrecorded field")) +
            ", this study's holds \"" + pointer.get<std::string>() +
            "\" (another study's results? remove the file or name another --out)");
  }
  WriteWhole(path, [&](std::ostream& f) { f << now.dump(1) << '\n'; });
}

/// Writes the header and the rows to `path`, whole at every moment (WriteWhole).
void WriteAll(const std::string& path, const std::string& header,
              const std::map<std::uint64_t, std::string>& rows) {
  WriteWhole(path, [&](std::ostream& f) {
    f << header << '\n';
    for (const auto& [k, line] : rows) f << line << '\n';
  });
}

}  // namespace

std::string SweepHeader(const io::Study& study) {
  std::string h = "index";
  for (const io::StudyParameter& p : study.parameters) h += "," + Field(p.path);
  for (const io::StudyOutput& o : study.outputs) h += "," + Field(o.name);
  return h + ",status,wall_time_s";
}

SweepFile::SweepFile(const io::Study& study, const std::string& path)
    : path_(path), header_(SweepHeader(study)), points_(study.PointCount()) {
  const std::filesystem::path directory = std::filesystem::path(path_).parent_path();
  std::error_code ec;
  if (!directory.empty() && !std::filesystem::is_directory(directory, ec))
    throw std::runtime_error(path_ + ": cannot write (" +
                             (ec ? ec.message() : "no directory " + directory.string()) + ")");
  // One writer per file: two processes on one --out (srun's tasks that no MPI joins, two jobs)
  // would each run the whole study into it. An advisory lock on `<csv>.lock`, held until done.
  const std::string lock = path_ + ".lock";
  lock_.fd = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock_.fd < 0)
    throw std::runtime_error(lock + ": cannot open (" + std::strerror(errno) + ")");
  if (::flock(lock_.fd, LOCK_EX | LOCK_NB) != 0)
    throw std::runtime_error(path_ + ": another sweep is writing it (" + lock + " is locked); "
                             "tasks that should share a study must be MPI ranks (mpirun, or "
                             "srun --mpi=pmix), not separate processes");
  rows_ = ReadRows(path_, header_, points_, &dropped_);
  CheckResumedPoints(path_, study, rows_);
  CheckAndRecordProblem(path_, study, !rows_.empty());
  CheckAndRecordOutputs(path_, study, !rows_.empty());
  resumed_ = rows_.size();
  WriteAll(path_, header_, rows_);  // drops a torn line; the file now ends with a whole row
  for (std::uint64_t k = 0; k < points_; ++k)
    if (!rows_.count(k)) pending_.push_back(k);
  status_column_ = 1 + study.parameters.size() + study.outputs.size();
  for (const io::StudyOutput& o : study.outputs)
    outputs_.push_back("\"" + o.name + "\" (" + o.path + ")");
  fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND);
  if (fd_ < 0) throw std::runtime_error(path_ + ": cannot open for appending");
}

SweepFile::OwnedFd::~OwnedFd() {
  if (fd >= 0) ::close(fd);
}

SweepFile::~SweepFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::uint64_t SweepFile::Append(std::uint64_t k, const std::string& row) {
  const std::string line = row + '\n';
  std::lock_guard<std::mutex> lock(mutex_);
  // One write of the whole line: a kill leaves it whole or absent.
  if (::write(fd_, line.data(), line.size()) != static_cast<ssize_t>(line.size()))
    write_failed_ = true;
  if (!rows_.count(k)) ++ran_;
  rows_[k] = row;
  return rows_.size();
}

SweepSummary SweepFile::Finish() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (write_failed_) throw std::runtime_error(path_ + ": a row could not be written");
  SweepSummary s;
  s.points = points_;
  s.resumed = resumed_;
  s.ran = ran_;
  s.dropped = dropped_;
  s.complete = rows_.size() == points_;
  if (s.complete) WriteAll(path_, header_, rows_);  // in point order
  const std::size_t first_output = status_column_ - outputs_.size();
  std::vector<bool> seen(outputs_.size(), false);
  bool any_converged = false;
  for (const auto& [k, line] : rows_) {
    if (line.compare(StartOfField(line, status_column_), 10, "converged,") != 0) {
      ++s.failed;
      continue;
    }
    any_converged = true;
    for (std::size_t j = 0; j < outputs_.size(); ++j)
      if (!seen[j]) seen[j] = line[StartOfField(line, first_output + j)] != ',';
  }
  for (std::size_t j = 0; j < outputs_.size() && any_converged; ++j)
    if (!seen[j]) s.empty_outputs.push_back(outputs_[j]);
  return s;
}

SweepSummary RunSweep(const io::Study& study, const std::string& csv_path,
                      const SweepOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  SweepFile file(study, csv_path);
  std::vector<std::uint64_t> pending = file.pending();
  if (options.max_new_points > 0 && pending.size() > options.max_new_points)
    pending.resize(options.max_new_points);
  const std::uint64_t total = study.PointCount();
  std::mutex progress_mutex;
  std::atomic<bool> stop{false};
  auto point = [&](std::size_t i) {
    if (stop.load()) return;
    const std::uint64_t done = file.Append(pending[i], SweepPointRow(study, pending[i]));
    if (options.progress || options.keep_going) {
      std::lock_guard<std::mutex> lock(progress_mutex);
      if (options.progress) options.progress(done, total);
      if (options.keep_going && !options.keep_going()) stop = true;
    }
  };
  // No more threads than points, whatever --threads asks for.
  const int threads = static_cast<int>(
      std::clamp<std::uint64_t>(static_cast<std::uint64_t>(std::max(1, options.threads)), 1,
                                std::max<std::uint64_t>(1, pending.size())));
  ThreadTeam(threads).For(pending.size(), point);
  SweepSummary summary = file.Finish();
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return summary;
}

}  // namespace cosserat::run

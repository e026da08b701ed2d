#include "cosserat/run/sweep.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "cosserat/io/problem.hpp"
#include "cosserat/run/run.hpp"

namespace cosserat::run {
namespace {

using json = nlohmann::json;

std::string Number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

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
  if (v.is_number()) return Number(v.get<double>());
  if (v.is_string()) return Field(v.get<std::string>());
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_null()) return "";
  return Field(v.dump());
}

/// Runs point k; its row without the line break.
std::string RunPoint(const io::Study& study, std::uint64_t k) {
  const auto t0 = std::chrono::steady_clock::now();
  std::ostringstream row;
  row << k;
  for (double v : study.Point(k)) row << ',' << Number(v);
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
  row << ',' << Field(status) << ',' << Number(wall);
  return row.str();
}

/// The rows already in the file (whole lines after the study's header), by point index.
std::map<std::uint64_t, std::string> ReadRows(const std::string& path, const std::string& header,
                                              std::uint64_t points) {
  std::map<std::uint64_t, std::string> rows;
  std::ifstream f(path, std::ios::binary);
  if (!f) return rows;
  std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (text.empty()) return rows;
  std::size_t end = text.find('\n');
  if (end == std::string::npos || text.substr(0, end) != header)
    throw std::runtime_error(path + ": its header is not this study's (another study's results?)");
  for (std::size_t start = end + 1; start < text.size(); start = end + 1) {
    end = text.find('\n', start);
    if (end == std::string::npos) break;  // a torn last line: the point runs again
    const std::string line = text.substr(start, end - start);
    std::size_t used = 0;
    try {
      const unsigned long long k = std::stoull(line, &used);
      if (used > 0 && used < line.size() && line[used] == ',' && k < points) rows[k] = line;
    } catch (const std::exception&) {
      // not a row: dropped
    }
  }
  return rows;
}

/// Writes the header and the rows to `path` through a temporary file and a rename, so that the
/// file is whole at every moment.
void WriteAll(const std::string& path, const std::string& header,
              const std::map<std::uint64_t, std::string>& rows) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    f << header << '\n';
    for (const auto& [k, line] : rows) f << line << '\n';
    if (!f) throw std::runtime_error(tmp + ": cannot write");
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace

std::string SweepHeader(const io::Study& study) {
  std::string h = "index";
  for (const io::StudyParameter& p : study.parameters) h += "," + Field(p.path);
  for (const io::StudyOutput& o : study.outputs) h += "," + Field(o.name);
  return h + ",status,wall_time_s";
}

SweepSummary RunSweep(const io::Study& study, const std::string& csv_path,
                      const SweepOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  SweepSummary summary;
  summary.points = study.PointCount();
  const std::string header = SweepHeader(study);
  std::map<std::uint64_t, std::string> rows = ReadRows(csv_path, header, summary.points);
  summary.resumed = rows.size();
  WriteAll(csv_path, header, rows);  // drops a torn line; the file now ends with a whole row

  std::vector<std::uint64_t> pending;
  for (std::uint64_t k = 0; k < summary.points; ++k)
    if (!rows.count(k)) pending.push_back(k);
  if (options.max_new_points > 0 && pending.size() > options.max_new_points)
    pending.resize(options.max_new_points);

  const int fd = ::open(csv_path.c_str(), O_WRONLY | O_APPEND);
  if (fd < 0) throw std::runtime_error(csv_path + ": cannot open for appending");
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  std::uint64_t done = summary.resumed;
  bool write_failed = false;
  auto worker = [&] {
    for (std::size_t i = next++; i < pending.size(); i = next++) {
      const std::string line = RunPoint(study, pending[i]) + '\n';
      std::lock_guard<std::mutex> lock(mutex);
      // One write of the whole line: a kill leaves it whole or absent.
      if (::write(fd, line.data(), line.size()) != static_cast<ssize_t>(line.size()))
        write_failed = true;
      rows[pending[i]] = line.substr(0, line.size() - 1);
      ++summary.ran;
      if (options.progress) options.progress(++done, summary.points);
    }
  };
  std::vector<std::thread> threads;
  for (int t = 1; t < std::max(1, options.threads); ++t) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
  ::close(fd);
  if (write_failed) throw std::runtime_error(csv_path + ": a row could not be written");

  summary.complete = rows.size() == summary.points;
  if (summary.complete) WriteAll(csv_path, header, rows);  // in point order
  const std::size_t status_column = 1 + study.parameters.size() + study.outputs.size();
  for (const auto& [k, line] : rows) {
    std::size_t pos = 0;
    for (std::size_t c = 0; c < status_column; ++c) pos = line.find(',', pos) + 1;
    if (line.compare(pos, 10, "converged,") != 0) ++summary.failed;
  }
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return summary;
}

}  // namespace cosserat::run

// Studies and sweeps (io/study.hpp, run/sweep.hpp): a study's points, its bad files named by
// field, and `cosserat sweep`'s rows: the arc of a tendon-bent backbone at every tension, the
// same rows on one and on two threads, a study stopped part-way and resumed running every point
// exactly once, a torn last line run again, a failing point kept as a row with its status, and
// the rows of another grid or another problem refused rather than resumed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cosserat/io/study.hpp"
#include "cosserat/run/sweep.hpp"

namespace cosserat {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// A spring-steel backbone (L = 0.25 m, r = 0.4 mm) with one straight tendon 8 mm off its axis,
/// no gravity: a tension T bends it into an arc of curvature T r/EI.
const char* kTendonRobot = R"({
  "format": "cosserat-problem/1", "analysis": "statics",
  "rod": { "length": 0.25, "nodes": 41, "section": { "shape": "circle", "radius": 0.0004 },
           "material": { "youngs_modulus": 210e9, "shear_modulus": 80e9, "density": 7800 } },
  "robot": { "kind": "tendon", "disk_radius": 0.01,
             "tendons": [ { "name": "t", "route": "parallel", "offset": [0.008, 0] } ],
             "actuation": { "tension": [0.0] } } })";

std::string TendonStudy(const std::string& parameters) {
  return std::string(R"({"format": "cosserat-study/1", "problem": )") + kTendonRobot +
         R"(, "parameters": )" + parameters +
         R"(, "outputs": {"tip_x": "/tip/position/0", "tip_z": "/tip/position/2"}})";
}

io::Study Parse(const std::string& text) {
  io::StudyParseResult r = io::ParseStudy(text, "<test>", ".");
  std::string errors;
  for (const std::string& e : r.errors) errors += e + "\n";
  EXPECT_TRUE(r.study.has_value()) << errors;
  return r.study ? *r.study : io::Study{};
}

std::vector<std::string> Errors(const std::string& text) {
  return io::ParseStudy(text, "<test>", ".").errors;
}

bool HasError(const std::vector<std::string>& errors, const std::string& part) {
  for (const std::string& e : errors)
    if (e.find(part) != std::string::npos) return true;
  return false;
}

/// A study's CSV in the temporary directory, with the files a sweep keeps beside it (partial
/// rows, lock, the records a resume checks): none before the test and none left after it.
class TempStudy {
 public:
  explicit TempStudy(const std::string& name)
      : path_((std::filesystem::temp_directory_path() / ("cosserat_test_study_" + name))
                  .string()) {
    Remove();
  }
  ~TempStudy() { Remove(); }
  TempStudy(const TempStudy&) = delete;
  TempStudy& operator=(const TempStudy&) = delete;
  const std::string& path() const { return path_; }
  /// Removes the CSV and everything recorded beside it.
  void Remove() const {
    for (const char* end : {"", ".tmp", ".lock", ".problem.json", ".outputs.json"})
      std::remove((path_ + end).c_str());
  }

 private:
  std::string path_;
};

/// The rows of a CSV file without their last column (the timing), by index; the header too.
std::map<long, std::string> Rows(const std::string& path, std::string* header = nullptr) {
  std::ifstream f(path);
  std::string line;
  std::getline(f, line);
  if (header) *header = line;
  std::map<long, std::string> rows;
  while (std::getline(f, line)) {
    const long k = std::stol(line);
    EXPECT_EQ(rows.count(k), 0u) << "point " << k << " twice";
    rows[k] = line.substr(0, line.rfind(','));
  }
  return rows;
}

TEST(Study, PointsAreTheGridProductRepeatedForTheRandomDraws) {
  const io::Study s = Parse(R"({"format": "cosserat-study/1", "problem": )" +
                            std::string(kTendonRobot) + R"(, "samples": 3, "seed": 11,
    "parameters": [ {"path": "/rod/length", "grid": {"from": 0.2, "to": 0.3, "count": 3}},
                    {"path": "/robot/actuation/tension/0", "values": [0.5, 1.0]},
                    {"path": "/rod/material/density", "random": {"distribution": "uniform", "low": 7000, "high": 8000}} ],
    "outputs": {"tip_x": "/tip/position/0"}})");
  ASSERT_EQ(s.PointCount(), 3u * 2u * 3u);
  // Point k = (grid index) × samples + draw: the last grid parameter varies fastest.
  EXPECT_DOUBLE_EQ(s.Point(0)[0], 0.2);
  EXPECT_DOUBLE_EQ(s.Point(3)[1], 1.0);
  EXPECT_DOUBLE_EQ(s.Point(6)[0], 0.25);
  EXPECT_DOUBLE_EQ(s.Point(17)[0], 0.3);
  for (std::uint64_t k = 0; k < s.PointCount(); ++k) {
    const double rho = s.Point(k)[2];
    EXPECT_GE(rho, 7000.0);
    EXPECT_LT(rho, 8000.0);
    EXPECT_EQ(rho, s.Point(k)[2]);  // a point's draw depends only on the seed and k
  }
  EXPECT_NE(s.Point(0)[2], s.Point(1)[2]);
  EXPECT_EQ(s.PointProblem(6)["rod"]["length"].get<double>(), 0.25);
}

// A grid's ends are its "from" and "to" exactly (0.001 + (0.01 − 0.001) · 3/3 is
// 0.010000000000000002 in doubles).
TEST(Study, AGridEndsExactlyAtItsEnds) {
  const io::Study s = Parse(R"({"format": "cosserat-study/1", "problem": )" +
                            std::string(kTendonRobot) + R"(,
    "parameters": [ {"path": "/robot/actuation/tension/0",
                     "grid": {"from": 0.001, "to": 0.01, "count": 4}} ],
    "outputs": {"tip_x": "/tip/position/0"}})");
  ASSERT_EQ(s.PointCount(), 4u);
  EXPECT_EQ(s.Point(0)[0], 0.001);
  EXPECT_EQ(s.Point(3)[0], 0.01);
  EXPECT_DOUBLE_EQ(s.Point(1)[0], 0.004);
}

// A grid's values are numpy.linspace's, to the bit, so that a notebook's filter on a value finds
// its rows: numpy 1.24 gives linspace(0.3, 1.2, 10) = 0.3, 0.39999999999999997, 0.5, 0.6, 0.7,
// 0.7999999999999999, 0.8999999999999999, 1.0, 1.0999999999999999, 1.2 (from + i (to − from) / 9
// gave 0.9999999999999998 at i = 7).
TEST(Study, AGridHoldsNumpyLinspacesValues) {
  const io::Study s = Parse(TendonStudy(
      R"([{"path": "/robot/actuation/tension/0",
           "grid": {"from": 0.3, "to": 1.2, "count": 10}}])"));
  const std::vector<double> numpy = {0.3, 0.39999999999999997, 0.5, 0.6, 0.7, 0.7999999999999999,
                                     0.8999999999999999, 1.0, 1.0999999999999999, 1.2};
  ASSERT_EQ(s.PointCount(), numpy.size());
  for (std::size_t i = 0; i < numpy.size(); ++i) EXPECT_EQ(s.Point(i)[0], numpy[i]) << i;
}

// The normal draws have the asked mean and spread: over 20 000 draws the sample mean is within
// 4 σ/√n of μ (a false failure once in ~16 000 runs; the draws are fixed by the seed, so never)
// and the sample deviation within 2 %.
TEST(Study, NormalDrawsHaveTheirMeanAndDeviation) {
  const io::Study s = Parse(R"({"format": "cosserat-study/1", "problem": )" +
                            std::string(kTendonRobot) + R"(, "samples": 20000,
    "parameters": [ {"path": "/rod/material/density", "random": {"distribution": "normal", "mean": 7800, "std": 50}} ],
    "outputs": {"tip_x": "/tip/position/0"}})");
  double sum = 0, sq = 0;
  const std::uint64_t n = s.PointCount();
  for (std::uint64_t k = 0; k < n; ++k) {
    const double x = s.Point(k)[0];
    sum += x;
    sq += x * x;
  }
  const double mean = sum / n, sd = std::sqrt(sq / n - mean * mean);
  EXPECT_NEAR(mean, 7800, 4 * 50 / std::sqrt(double(n)));
  EXPECT_NEAR(sd, 50, 0.02 * 50);
}

TEST(Study, BadStudiesNameTheField) {
  std::vector<std::string> e = Errors(TendonStudy(R"([{"path": "/rod/nosuch/x", "values": [1]}])"));
  EXPECT_TRUE(HasError(e, "parameters[0].path: names \"/rod/nosuch/x\", but the problem has no \"/rod/nosuch\""));
  e = Errors(TendonStudy(R"([{"path": "/rod/lenght", "values": [1]}])"));
  EXPECT_TRUE(HasError(e, "rod.lenght: unknown key")) << e.front();
  e = Errors(TendonStudy(R"([{"path": "/rod/length", "grid": {"from": 0.2, "to": 0.2, "count": 3}}])"));
  EXPECT_TRUE(HasError(e, "parameters[0].grid.to: an empty range"));
  e = Errors(TendonStudy(R"([{"path": "/rod/length", "values": []}])"));
  EXPECT_TRUE(HasError(e, "parameters[0].values: expected a non-empty array of numbers"));
  e = Errors(TendonStudy(
      R"([{"path": "/rod/length", "random": {"distribution": "uniform", "low": 0.3, "high": 0.2}}])"));
  EXPECT_TRUE(HasError(e, "parameters[0].random.high: expected a bound above \"low\""));
  e = Errors(TendonStudy(
      R"([{"path": "/rod/length", "random": {"distribution": "normal", "mean": 0.3, "std": -1}}])"));
  EXPECT_TRUE(HasError(e, "parameters[0].random.std: expected a positive number"));
  e = Errors(TendonStudy(
      R"([{"path": "/rod/length", "random": {"distribution": "cauchy", "low": 0, "high": 1}}])"));
  EXPECT_TRUE(HasError(e, "parameters[0].random.distribution"));
  e = Errors(TendonStudy(R"([{"path": "/rod/length", "values": [1], "grid": {"from": 0, "to": 1, "count": 2}}])"));
  EXPECT_TRUE(HasError(e, "parameters[0]: expected exactly one of"));
  // Paths that point inside a number or past an array's end, or at the whole problem.
  e = Errors(TendonStudy(R"([{"path": "/rod/nodes/0", "values": [1]}])"));
  EXPECT_TRUE(HasError(e, "parameters[0].path: names \"/rod/nodes/0\", inside \"/rod/nodes\""));
  for (const char* past_the_end : {"/1", "/-1", "/-", "/~1", "/00"}) {
    e = Errors(TendonStudy(std::string(R"([{"path": "/robot/actuation/tension)") + past_the_end +
                           R"(", "values": [1]}])"));
    EXPECT_TRUE(HasError(e, "is an array of 1 value, so the last part must be an index below 1"))
        << past_the_end;
  }
  e = Errors(TendonStudy(R"([{"path": "rod/length", "values": [1]}])"));
  EXPECT_TRUE(HasError(e, "parameters[0].path: expected a JSON pointer such as \"/rod/length\" (it "
                          "starts with \"/\"), got \"rod/length\""));
  EXPECT_FALSE(HasError(e, "json.exception"));  // the parser's own text is not the user's
  e = Errors(TendonStudy(R"([{"path": "", "values": [1]}, {"path": "/rod/length", "values": [1]}])"));
  EXPECT_TRUE(HasError(e, "parameters[0].path: expected a pointer to a value inside the problem"));
  // Too many points for the sweep's memory: named, whatever the product.
  e = Errors(TendonStudy(
      R"([{"path": "/rod/length", "grid": {"from": 0.1, "to": 0.2, "count": 1000000}},
          {"path": "/robot/actuation/tension/0", "grid": {"from": 0, "to": 1, "count": 1000000}}])"));
  EXPECT_TRUE(HasError(e, "parameters: expected at most 10000000 points in all"));
  // An output named like a parameter's column: two CSV columns of one name.
  e = Errors(std::string(R"({"format": "cosserat-study/1", "problem": )") + kTendonRobot +
             R"(, "parameters": [{"path": "/rod/length", "values": [0.25]}],
                 "outputs": {"/rod/length": "/tip/position/0"}})");
  EXPECT_TRUE(HasError(e, "outputs[\"/rod/length\"]: expected a name other than a parameter's "
                          "column (parameters[0] is named so)"));
  // A column named "" or across two lines; one grid point that drops "to"; draws with nothing
  // random, which repeat one point.
  e = Errors(std::string(R"({"format": "cosserat-study/1", "problem": )") + kTendonRobot +
             R"(, "parameters": [{"path": "/rod/length", "values": [0.25]}],
                 "outputs": {"": "/tip/position/0", "a\nb": "/tip/position/1"}})");
  EXPECT_TRUE(HasError(e, "outputs[\"\"]: expected a column name, not empty and on one line"));
  EXPECT_TRUE(HasError(e, "expected a column name, not empty and on one line, got \"a"));
  e = Errors(TendonStudy(
      R"([{"path": "/rod/length", "grid": {"from": 0.2, "to": 0.3, "count": 1}}])"));
  EXPECT_TRUE(HasError(e, "parameters[0].grid.count: 1 point holds \"from\" only"));
  EXPECT_TRUE(Errors(TendonStudy(
      R"([{"path": "/rod/length", "grid": {"from": 0.2, "to": 0.2, "count": 1}}])")).empty());
  e = Errors(std::string(R"({"format": "cosserat-study/1", "problem": )") + kTendonRobot +
             R"(, "samples": 3, "parameters": [{"path": "/rod/length", "values": [0.25]}],
                 "outputs": {"x": "/tip/position/0"}})");
  EXPECT_TRUE(HasError(e, "samples: expected 1 when no parameter is random"));
}

// A value invalid at some points only (a negative length in a list) is not the study's mistake:
// those points run as rows with their reason, wherever they stand in the list, and
// CheckStudyPoints counts them. A study none of whose points is a problem is refused, naming
// point 0's values.
TEST(Study, PointsInvalidHereAndThereAreRowsNotARefusal) {
  for (const char* values : {"[0.25, -0.1, 0.2]", "[-0.1, 0.25, 0.2]"}) {
    const io::Study s = Parse(TendonStudy(std::string(R"([{"path": "/rod/length", "values": )") +
                                          values + "}]"));
    const io::StudyPointCheck check = io::CheckStudyPoints(s, 100);
    EXPECT_EQ(check.checked, 3u);
    EXPECT_EQ(check.invalid, 1u) << values;
    EXPECT_EQ(s.Point(check.first)[0], -0.1);
    EXPECT_NE(check.first_error.find("rod.length"), std::string::npos) << check.first_error;
  }
  const std::vector<std::string> e =
      Errors(TendonStudy(R"([{"path": "/rod/length", "values": [-0.1, -0.2]}])"));
  EXPECT_TRUE(HasError(e, "problem (with point 0's parameters: /rod/length = -0.1)"))
      << (e.empty() ? "" : e.front());
}

// Each row's tip is the arc's: the tendon's moment T r bends the backbone to κ = T r/EI and its
// pull compresses it by T/EA, so x = (1 − T/EA)(1 − cos κL)/κ, z = (1 − T/EA) sin(κL)/κ. RK4
// on the constant curvature (κh ≤ 0.024) errs by ~(κh)⁵/120 per step: 1e-8 L bounds it.
TEST(Sweep, EveryRowIsTheArcOfItsTension) {
  const io::Study s = Parse(TendonStudy(
      R"([{"path": "/robot/actuation/tension/0", "grid": {"from": 0, "to": 2, "count": 9}}])"));
  const TempStudy study("arc.csv");
  const std::string& path = study.path();
  const run::SweepSummary sum = run::RunSweep(s, path);
  ASSERT_TRUE(sum.complete);
  EXPECT_EQ(sum.failed, 0u);
  const double L = 0.25, EI = 210e9 * kPi * std::pow(0.0004, 4) / 4;
  const double EA = 210e9 * kPi * 0.0004 * 0.0004;
  std::ifstream f(path);
  std::string line;
  std::getline(f, line);
  int n = 0;
  while (std::getline(f, line)) {
    std::stringstream row(line);
    std::string cell;
    std::vector<std::string> c;
    while (std::getline(row, cell, ',')) c.push_back(cell);
    const double T = std::stod(c[1]), x = std::stod(c[2]), z = std::stod(c[3]);
    const double k = T * 0.008 / EI, stretch = 1 - T / EA;
    const double x_arc = k > 0 ? stretch * (1 - std::cos(k * L)) / k : 0.0;
    const double z_arc = k > 0 ? stretch * std::sin(k * L) / k : L;
    EXPECT_NEAR(x, x_arc, 1e-8 * L) << "T = " << T;
    EXPECT_NEAR(z, z_arc, 1e-8 * L) << "T = " << T;
    EXPECT_EQ(c[4], "converged");
    ++n;
  }
  EXPECT_EQ(n, 9);
}

TEST(Sweep, OneAndTwoThreadsGiveTheSameRows) {
  const io::Study s = Parse(TendonStudy(
      R"([{"path": "/robot/actuation/tension/0", "grid": {"from": 0, "to": 2, "count": 15}},
          {"path": "/rod/material/youngs_modulus", "values": [2.0e11, 2.1e11, 2.2e11]}])"));
  const TempStudy study_one("one.csv"), study_two("two.csv");
  const std::string &one = study_one.path(), &two = study_two.path();
  run::SweepOptions o;
  o.threads = 1;
  run::RunSweep(s, one, o);
  o.threads = 2;
  run::RunSweep(s, two, o);
  std::string h1, h2;
  EXPECT_EQ(Rows(one, &h1), Rows(two, &h2));
  EXPECT_EQ(h1, h2);
  EXPECT_EQ(Rows(one).size(), 45u);
}

// Stopped after 10 points, resumed on two threads: every point once, the rows of a run that was
// never stopped. A torn last line (a kill in the middle of a write) is dropped and its point run
// again.
TEST(Sweep, AStoppedStudyResumesAndRunsEveryPointOnce) {
  const io::Study s = Parse(TendonStudy(
      R"([{"path": "/robot/actuation/tension/0", "grid": {"from": 0, "to": 2, "count": 30}}])"));
  const TempStudy study_whole("whole.csv"), study_parts("parts.csv");
  const std::string &whole = study_whole.path(), &parts = study_parts.path();
  run::RunSweep(s, whole);
  run::SweepOptions o;
  o.max_new_points = 10;
  run::SweepSummary first = run::RunSweep(s, parts, o);
  EXPECT_FALSE(first.complete);
  EXPECT_EQ(first.ran, 10u);
  std::string header, first_row;
  {
    std::ifstream f(parts);
    std::getline(f, header);
    std::getline(f, first_row);
  }
  {
    std::ofstream f(parts, std::ios::app);
    // Three lines that are no rows of this study, each counted as dropped: text, an index past
    // its 30 points, a point's second row (the later one is kept: here the same).
    f << "not a row\n" << "99,2,0.1,0.2,converged,0.001\n" << first_row << '\n';
    f << "29,2,0.1";  // a row cut short, without its line break: not counted
  }
  o.max_new_points = 0;
  o.threads = 2;
  const run::SweepSummary second = run::RunSweep(s, parts, o);
  EXPECT_TRUE(second.complete);
  EXPECT_EQ(second.resumed, 10u);
  EXPECT_EQ(second.ran, 20u);
  EXPECT_EQ(second.dropped, 3u);
  EXPECT_EQ(Rows(parts), Rows(whole));
}

TEST(Sweep, AFailingPointIsARowWithItsStatus) {
  const io::Study s = Parse(TendonStudy(
      R"([{"path": "/rod/length", "values": [0.25, -0.1, 0.2]}])"));
  const TempStudy study("failing.csv");
  const std::string& path = study.path();
  const run::SweepSummary sum = run::RunSweep(s, path);
  EXPECT_TRUE(sum.complete);
  EXPECT_EQ(sum.failed, 1u);
  const std::map<long, std::string> rows = Rows(path);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_NE(rows.at(1).find("invalid: rod.length: expected a positive number"), std::string::npos)
      << rows.at(1);
  EXPECT_NE(rows.at(2).find("converged"), std::string::npos);
}

// One writer per file: a second sweep started on the same --out while the first runs (two
// jobs, or srun tasks that no MPI joins) is refused, naming the lock, instead of running the
// whole study into it too; the lock goes with the first.
TEST(Sweep, ASecondWriterOnOneFileIsRefused) {
  const io::Study s = Parse(TendonStudy(R"([{"path": "/rod/length", "values": [0.25]}])"));
  const TempStudy study("locked.csv");
  const std::string& path = study.path();
  {
    run::SweepFile first(s, path);
    try {
      run::SweepFile second(s, path);
      ADD_FAILURE() << "a second writer was let in";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("another sweep is writing it"), std::string::npos)
          << e.what();
    }
  }
  EXPECT_NO_THROW(run::SweepFile again(s, path));
}

// A result's null is written "nan", as the docs say: a buckling search capped at 0.1 N on a
// 0.3 m wire, whose Euler load π²EI/4L² is 4.3 N, finds no critical load. "/warnings" gives the
// log's warnings as a JSON list, [] where there are none.
TEST(Sweep, ANullIsNanAndWarningsAreAColumn) {
  const io::Study s = Parse(R"({"format": "cosserat-study/1", "problem": {
      "format": "cosserat-problem/1", "analysis": "buckling",
      "rod": {"length": 0.3, "nodes": 21, "section": {"shape": "circle", "radius": 0.001},
              "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000}},
      "loads": {"gravity": [0, 0, 0]},
      "buckling": {"load": "tip_force", "direction": [0, 0, -1], "max": 0.1}},
    "parameters": [{"path": "/loads/gravity/0", "values": [0, -5000]}],
    "outputs": {"p": "/buckling/critical_load", "w": "/warnings"}})");
  const TempStudy study("nan.csv");
  const std::string& path = study.path();
  run::RunSweep(s, path);
  const std::map<long, std::string> rows = Rows(path);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows.at(0).find("0,0,nan,[],"), 0u) << rows.at(0);
  EXPECT_NE(rows.at(1).find("\"[\"\"loads.gravity is 5e+03 m/s²"), std::string::npos) << rows.at(1);
}

TEST(Sweep, AFileOfAnotherStudyIsNotOverwritten) {
  const io::Study s = Parse(TendonStudy(R"([{"path": "/rod/length", "values": [0.25]}])"));
  const TempStudy study("other.csv");
  const std::string& path = study.path();
  {
    std::ofstream f(path);
    f << "index,something,else\n0,1,2\n";
  }
  try {
    run::RunSweep(s, path);
    ADD_FAILURE() << "not refused";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("column 2 is something, this study's /rod/length"),
              std::string::npos)
        << e.what();
  }
  std::ifstream f(path);
  std::string first;
  std::getline(f, first);
  EXPECT_EQ(first, "index,something,else");
}

// The header names the columns, not the fields they hold: a study whose tip_x now reads
// /tip/position/1 would mix y into a column of x. The fields are recorded beside the file, and
// such a study is refused, naming the column; an unreadable record too. The same study resumes,
// and so do rows written before fields were recorded (no record: the header is all there is).
TEST(Sweep, AColumnThatNowHoldsAnotherFieldIsNotResumed) {
  const std::string grid = R"([{"path": "/robot/actuation/tension/0", "grid": {"from": 0, "to": 2,
                               "count": 3}}])";
  const TempStudy study("fields.csv");
  const std::string& path = study.path();
  run::SweepOptions o;
  o.max_new_points = 2;
  run::RunSweep(Parse(TendonStudy(grid)), path, o);
  const std::map<long, std::string> before = Rows(path);
  ASSERT_EQ(before.size(), 2u);
  std::string moved = TendonStudy(grid);
  moved.replace(moved.find("/tip/position/0"), 15, "/tip/position/1");
  try {
    run::RunSweep(Parse(moved), path);
    ADD_FAILURE() << "not refused";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("its column tip_x holds \"/tip/position/0\", this "
                                         "study's holds \"/tip/position/1\""),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(Rows(path), before);
  const std::string record = path + ".outputs.json";
  std::ofstream(record) << "{\"tip_x\": ";  // torn
  EXPECT_THROW(run::RunSweep(Parse(TendonStudy(grid)), path), std::runtime_error);
  std::remove(record.c_str());
  EXPECT_EQ(run::RunSweep(Parse(TendonStudy(grid)), path).resumed, 2u);
  EXPECT_THROW(run::RunSweep(Parse(moved), path), std::runtime_error);  // recorded again
}

// A file that has this study's columns but another study's points (another grid) or rows of
// another problem (its rod 0.3 m long, recorded beside the file) is refused before any row is
// written, naming what differs; the rows stay as they were.
TEST(Sweep, RowsOfAnotherGridOrProblemAreNotResumed) {
  const std::string grid = R"([{"path": "/robot/actuation/tension/0", "grid": {"from": 0, "to": 2,
                               "count": 3}}])";
  const TempStudy study("resumed.csv");
  const std::string& path = study.path();
  run::SweepOptions o;
  o.max_new_points = 2;
  run::RunSweep(Parse(TendonStudy(grid)), path, o);
  const std::map<long, std::string> before = Rows(path);
  ASSERT_EQ(before.size(), 2u);
  auto refusal = [&](const io::Study& s) {
    try {
      run::RunSweep(s, path);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("not refused");
  };
  std::string other_grid = grid;
  other_grid.replace(other_grid.find("\"to\": 2"), 7, "\"to\": 1");
  EXPECT_NE(refusal(Parse(TendonStudy(other_grid))).find("point 1 has /robot/actuation/tension/0 = "
                                                          "1, this study's point has 0.5"),
            std::string::npos);
  std::string longer = TendonStudy(grid);
  longer.replace(longer.find("\"length\": 0.25"), 14, "\"length\": 0.30");
  EXPECT_NE(refusal(Parse(longer)).find("differs at /rod/length"), std::string::npos);
  EXPECT_EQ(Rows(path), before);
  // Without the record of their problem the rows could be anyone's.
  const std::string record = path + ".problem.json", kept = path + ".kept";
  std::filesystem::rename(record, kept);
  EXPECT_NE(refusal(Parse(TendonStudy(grid))).find("its rows' problem is not recorded"),
            std::string::npos);
  std::filesystem::rename(kept, record);
  // The base value at a swept path does not count (each point sets it): the study resumes.
  std::string other_base = TendonStudy(grid);
  other_base.replace(other_base.find("\"tension\": [0.0]"), 16, "\"tension\": [9.0]");
  EXPECT_EQ(run::RunSweep(Parse(other_base), path).resumed, 2u);
}

// Rows are matched to their points by value: a file that writes 0.1 as 0.10000000000000001 (17
// digits) resumes, and so does 0.10000000000000002, the next double (a grid computed another way,
// as before grids followed numpy.linspace, differs by such ulps); 0.100000000001 is another
// point and does not. An interior point of a grid, 0.2 + 0.5 · 2/5, written in 17 digits,
// resumes.
TEST(Sweep, RowsWrittenWithMoreDigitsResume) {
  const std::string grid = R"([{"path": "/robot/actuation/tension/0", "grid": {"from": 0.1,
                               "to": 0.3, "count": 3}}])";
  const TempStudy study("digits.csv");
  const std::string& path = study.path();
  run::SweepOptions o;
  o.max_new_points = 1;
  run::RunSweep(Parse(TendonStudy(grid)), path, o);
  // Rewrites the parameter field of row `row` of the file as `to`; returns what it held.
  auto rewrite = [&](int row, const std::string& to) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    std::string csv = text.str();
    const std::string lead = "\n" + std::to_string(row) + ",";
    const size_t at = csv.find(lead);
    if (at == std::string::npos) return std::string("no row ") + std::to_string(row);
    const size_t start = at + lead.size(), end = csv.find(',', start);
    const std::string held = csv.substr(start, end - start);
    csv.replace(start, end - start, to);
    std::ofstream(path) << csv;
    return held;
  };
  EXPECT_EQ(rewrite(0, "0.10000000000000001"), "0.1");
  EXPECT_EQ(run::RunSweep(Parse(TendonStudy(grid)), path, o).resumed, 1u);
  EXPECT_EQ(rewrite(0, "0.10000000000000002"), "0.10000000000000001");
  EXPECT_EQ(run::RunSweep(Parse(TendonStudy(grid)), path, o).resumed, 2u);
  EXPECT_EQ(rewrite(0, "0.100000000001"), "0.10000000000000002");
  EXPECT_THROW(run::RunSweep(Parse(TendonStudy(grid)), path, o), std::runtime_error);
  const std::string six = R"([{"path": "/robot/actuation/tension/0", "grid": {"from": 0.2,
                              "to": 0.7, "count": 6}}])";
  study.Remove();  // a new study in the same file
  o.max_new_points = 3;
  run::RunSweep(Parse(TendonStudy(six)), path, o);
  char wide[32];
  std::snprintf(wide, sizeof wide, "%.17g", 0.2 + (0.7 - 0.2) * 2 / 5);
  EXPECT_EQ(rewrite(2, wide), "0.4");  // 0.40000000000000002 in 17 digits
  EXPECT_EQ(run::RunSweep(Parse(TendonStudy(six)), path, o).resumed, 3u);
}

}  // namespace
}  // namespace cosserat

#include "cosserat/io/study.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "cosserat/io/json_document.hpp"
#include "cosserat/io/json_reader.hpp"
#include "cosserat/io/problem.hpp"
#include "cosserat/io/text_file.hpp"

namespace cosserat::io {
namespace {

using json = nlohmann::json;
using detail::ErrorReport;
using detail::ObjectReader;
using detail::Presence;

/// A uniform double in [0, 1) from (seed, point, parameter): SplitMix64 of their mix.
double UnitDraw(std::uint64_t seed, std::uint64_t point, std::uint64_t stream) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (point + 1) + 0xBF58476D1CE4E5B9ULL * (stream + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53;
}

void ParseParameter(const ObjectReader& o, StudyParameter* p) {
  o.AllowOnly({"path", "grid", "values", "random"});
  p->path = detail::ReadString(o, "path", Presence::kRequired).value_or("");
  const int kinds = o.Has("grid") + o.Has("values") + o.Has("random");
  if (kinds != 1) {
    o.report().Add(o.path(), "expected exactly one of \"grid\", \"values\", \"random\"");
    return;
  }
  if (const auto g = detail::ReadObject(o, "grid", Presence::kOptional)) {
    g->AllowOnly({"from", "to", "count"});
    const auto from = detail::ReadNumber(*g, "from", detail::AnyFiniteNumber(), Presence::kRequired);
    const auto to = detail::ReadNumber(*g, "to", detail::AnyFiniteNumber(), Presence::kRequired);
    const auto count = detail::ReadInteger(*g, "count", 1, 1000000, Presence::kRequired);
    if (from && to && count) {
      if (*count > 1 && *from == *to)
        g->report().Add(g->PathOf("to"), "an empty range: \"from\" equals \"to\" with " +
                                             std::to_string(*count) + " points");
      if (*count == 1 && *from != *to)
        g->report().Add(g->PathOf("count"), "1 point holds \"from\" only, not \"to\": give "
                                            "at least 2 points, or the one value in \"values\"");
      // As numpy.linspace computes them, so that a grid's values equal a notebook's: from + i
      // step with step = (to − from)/(count − 1), the last point exactly `to` (the formula can
      // miss it by an ulp).
      const double step = *count > 1 ? (*to - *from) / (*count - 1) : 0.0;
      for (int i = 0; i < *count; ++i)
        p->values.push_back(i > 0 && i == *count - 1 ? *to : *from + i * step);
    }
  }
  if (const json* v = o.Find("values")) {
    if (!v->is_array() || v->empty()) {
      o.report().Expected(o.PathOf("values"), "a non-empty array of numbers", detail::Describe(*v));
    } else {
      for (std::size_t i = 0; i < v->size(); ++i)
        if (const auto x = detail::CheckNumber((*v)[i], detail::ElementPath(o.PathOf("values"), i),
                                               detail::AnyFiniteNumber(), o.report()))
          p->values.push_back(*x);
    }
  }
  if (const auto r = detail::ReadObject(o, "random", Presence::kOptional)) {
    r->AllowOnly({"distribution", "low", "high", "mean", "std"});
    const auto kind =
        detail::ReadChoice(*r, "distribution", {"uniform", "normal"}, Presence::kRequired);
    if (kind == "uniform") {
      p->distribution = StudyParameter::Distribution::kUniform;
      p->a = detail::ReadNumber(*r, "low", detail::AnyFiniteNumber(), Presence::kRequired).value_or(0);
      p->b = detail::ReadNumber(*r, "high", detail::AnyFiniteNumber(), Presence::kRequired).value_or(1);
      if (r->Has("low") && r->Has("high") && !(p->a < p->b))
        r->report().Add(r->PathOf("high"), "expected a bound above \"low\" (" +
                                               detail::FormatNumber(p->a) + "), got " +
                                               detail::FormatNumber(p->b));
    } else if (kind == "normal") {
      p->distribution = StudyParameter::Distribution::kNormal;
      p->a = detail::ReadNumber(*r, "mean", detail::AnyFiniteNumber(), Presence::kRequired).value_or(0);
      p->b = detail::ReadNumber(*r, "std", detail::PositiveNumber(), Presence::kRequired).value_or(1);
    }
  }
}

/// The parameter's path must name a place in the base problem: a valid JSON pointer whose parent
/// exists (the key itself may be new: an optional key the base leaves out).
void CheckPath(const json& problem, const std::string& where, const std::string& path,
               ErrorReport* report) {
  try {
    const json::json_pointer pointer(path);
    if (pointer.empty()) {
      report->Add(where, "expected a pointer to a value inside the problem, got \"\"");
      return;
    }
    const json::json_pointer parent = pointer.parent_pointer();
    if (!problem.contains(parent)) {
      report->Add(where, "names " + detail::Quote(path) + ", but the problem has no " +
                             detail::Quote(parent.to_string()));
      return;
    }
    // The value goes into an object (any key) or an array (an existing index): not inside a
    // number or a string.
    const json& holder = problem.at(parent);
    const std::string key = pointer.back();
    const bool index = !key.empty() && key.size() <= 9 &&
                       key.find_first_not_of("0123456789") == std::string::npos &&
                       (key == "0" || key[0] != '0');
    if (holder.is_array() && !(index && std::stoul(key) < holder.size()))
      report->Add(where, "names " + detail::Quote(path) + ": " + detail::Quote(parent.to_string()) +
                             " is an array of " + std::to_string(holder.size()) +
                             (holder.size() == 1 ? " value" : " values") +
                             ", so the last part must be an index below " +
                             std::to_string(holder.size()));
    else if (!holder.is_object() && !holder.is_array())
      report->Add(where, "names " + detail::Quote(path) + ", inside " +
                             detail::Quote(parent.to_string()) + ", which is " +
                             detail::Describe(holder) + ", not an object or an array");
  } catch (const json::exception&) {  // not a pointer at all ("x", "rod/length")
    report->Add(where, "expected a JSON pointer such as \"/rod/length\" (it starts with \"/\"), "
                       "got " + detail::Quote(path));
  }
}

/// "problem": a path (relative to the study's directory) or the problem object itself.
void ReadProblem(const ObjectReader& top, const std::string& base_directory, Study* study_out) {
  ErrorReport& report = top.report();
  Study& study = *study_out;
  const json* problem = top.Find("problem");
  if (!problem) {
    report.Missing("problem", "a problem file's path or a problem object");
  } else if (problem->is_string()) {
    std::filesystem::path path(problem->get<std::string>());
    if (path.is_relative()) path = std::filesystem::path(base_directory) / path;
    std::string text, why;
    if (!ReadTextFile(path.string(), &text, &why)) {
      report.Add("problem", path.string() + ": cannot read the file (" + why + ")");
      return;
    }
    const detail::JsonDocument pd = detail::ParseJsonDocument(text, path.string());
    if (!pd.value)
      for (const std::string& e : pd.errors) report.Add("problem", e);
    else if (pd.value->is_object() && pd.value->contains("format") &&
             (*pd.value)["format"] == "cosserat-study/1")
      report.Expected("problem", "a problem file", path.string() + ", a study file");
    else
      study.problem = *pd.value;
  } else if (problem->is_object()) {
    study.problem = *problem;
  } else {
    report.Expected("problem", "a problem file's path or a problem object",
                    detail::Describe(*problem));
  }
}

/// "outputs": column name -> JSON pointer into each point's result.
void ReadOutputs(const ObjectReader& top, Study* study_out) {
  Study& study = *study_out;
  ErrorReport& report = top.report();
  if (const auto outputs = detail::ReadObject(top, "outputs", Presence::kRequired)) {
    for (const auto& [name, value] : outputs->value().items()) {
      const std::string where = outputs->PathOf(name);
      if (!value.is_string()) {
        report.Expected(where, "a JSON pointer into the result, such as \"/tip/position/0\"",
                        detail::Describe(value));
        continue;
      }
      if (name.empty() || name.find_first_of("\n\r") != std::string::npos) {
        report.Expected(where, "a column name, not empty and on one line", detail::Quote(name));
        continue;
      }
      if (name == "index" || name == "status" || name == "wall_time_s") {
        report.Expected(where, "a name other than the fixed columns index, status and wall_time_s",
                        detail::Quote(name));
        continue;
      }
      // A parameter's column is named by its path: an output of that name would give the CSV
      // two columns of one name, and the row dict of cosserat.sweep one key for both.
      const auto clash = std::find_if(
          study.parameters.begin(), study.parameters.end(),
          [&column = name](const StudyParameter& p) { return p.path == column; });
      if (clash != study.parameters.end()) {
        report.Expected(where,
                        "a name other than a parameter's column (parameters[" +
                            std::to_string(clash - study.parameters.begin()) + "] is named so)",
                        detail::Quote(name));
        continue;
      }
      try {
        (void)json::json_pointer(value.get<std::string>());
        study.outputs.push_back({name, value.get<std::string>()});
      } catch (const json::exception&) {
        report.Expected(where, "a JSON pointer such as \"/tip/position/0\"",
                        detail::Quote(value.get<std::string>()));
      }
    }
  }
}

/// A parameter's path against the earlier parameters': two on one place (the later would
/// overwrite the earlier at every point, and the CSV would show values that were never run), or
/// one inside another ("/robot/actuation/tension" and ".../tension/1": the outer one sets the
/// whole value, a number where the inner one looks for an array), reported at `where`.
void CheckPlaceApart(const std::vector<StudyParameter>& earlier, const std::string& path,
                     const std::string& where, ErrorReport* report) {
  auto inside = [](const std::string& inner, const std::string& outer) {
    return inner.size() > outer.size() && inner.compare(0, outer.size(), outer) == 0 &&
           inner[outer.size()] == '/';
  };
  for (std::size_t j = 0; j < earlier.size(); ++j) {
    const std::string& other = earlier[j].path;
    if (path.empty() || other.empty()) continue;
    const std::string index = "parameters[" + std::to_string(j) + "]";
    if (other == path)
      report->Expected(where, "a place no other parameter sets (" + index + " sets it)",
                       detail::Quote(path));
    else if (inside(path, other) || inside(other, path))
      report->Expected(where,
                       "a place apart from " + index + "'s " + detail::Quote(other) +
                           " (one sets the value the other lies in)",
                       detail::Quote(path));
  }
}

/// Checks that need the whole study: draws repeated with nothing random, and some point being a
/// valid problem. A path naming an unknown key fails at every point, a value out of range at its
/// own points only (they run as rows with their reason): up to 64 points spread over the study
/// are tried, and when none is valid the first one's errors are said, with its values.
void CheckPointsMakeProblems(const Study& study, ErrorReport* report_out) {
  ErrorReport& report = *report_out;
  if (study.samples > 1 &&
      std::none_of(study.parameters.begin(), study.parameters.end(),
                   [](const StudyParameter& p) {
                     return p.distribution != StudyParameter::Distribution::kNone;
                   })) {
    report.Expected("samples", "1 when no parameter is random (the draws would repeat one point)",
                    std::to_string(study.samples));
    return;
  }
  try {
    const std::uint64_t n = study.PointCount(), tries = std::min<std::uint64_t>(n, 64);
    std::vector<std::string> first_errors;
    for (std::uint64_t j = 0; j < tries; ++j) {
      const std::uint64_t k = tries > 1 ? j * (n - 1) / (tries - 1) : 0;
      const ParseResult point = ParseProblemDocument(study.PointProblem(k));
      if (point.errors.empty()) return;
      if (j == 0) first_errors = point.errors;
    }
    const std::string where = "problem (with point 0's parameters: " + PointWords(study, 0) + ")";
    for (const std::string& e : first_errors) report.Add(where, e);
  } catch (const json::exception& e) {  // a path CheckPath let through: still named
    report.Add("parameters", std::string("cannot be set in the problem (") + e.what() + ")");
  }
}

}  // namespace

std::uint64_t Study::PointCount() const {
  // Saturates instead of wrapping: many large grids must not count as a small study.
  constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
  std::uint64_t n = static_cast<std::uint64_t>(samples);
  for (const StudyParameter& p : parameters)
    if (!p.values.empty()) n = n > kMax / p.values.size() ? kMax : n * p.values.size();
  return n;
}

std::vector<double> Study::Point(std::uint64_t k) const {
  std::vector<double> out(parameters.size(), 0.0);
  std::uint64_t grid = k / static_cast<std::uint64_t>(samples);
  for (std::size_t j = parameters.size(); j-- > 0;) {  // the last grid parameter varies fastest
    const StudyParameter& p = parameters[j];
    if (p.values.empty()) continue;
    out[j] = p.values[grid % p.values.size()];
    grid /= p.values.size();
  }
  for (std::size_t j = 0; j < parameters.size(); ++j) {
    const StudyParameter& p = parameters[j];
    if (p.distribution == StudyParameter::Distribution::kUniform) {
      out[j] = p.a + (p.b - p.a) * UnitDraw(seed, k, 2 * j);
    } else if (p.distribution == StudyParameter::Distribution::kNormal) {  // Box–Muller
      const double u1 = 1.0 - UnitDraw(seed, k, 2 * j), u2 = UnitDraw(seed, k, 2 * j + 1);
      out[j] = p.a + p.b * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
    }
  }
  return out;
}

json Study::PointProblem(std::uint64_t k) const {
  json doc = problem;
  const std::vector<double> values = Point(k);
  for (std::size_t j = 0; j < parameters.size(); ++j)
    doc[json::json_pointer(parameters[j].path)] = values[j];
  return doc;
}

StudyParseResult ParseStudy(const std::string& text, const std::string& source_name,
                            const std::string& base_directory) {
  StudyParseResult result;
  detail::JsonDocument doc = detail::ParseJsonDocument(text, source_name);
  result.errors = std::move(doc.errors);
  if (!doc.value) return result;
  ErrorReport report;
  Study study;
  if (!doc.value->is_object()) {
    report.Expected("", "an object", detail::Describe(*doc.value));
  } else {
    const ObjectReader top(*doc.value, "", &report);
    const json* format = top.Find("format");
    if (format && *format == "cosserat-problem/1") {
      // A problem file given to `sweep`: that alone, not each of its keys a study lacks.
      report.Expected("format", "\"cosserat-study/1\" (a problem file runs with `cosserat "
                                "solve`, or is a study's \"problem\")",
                      "\"cosserat-problem/1\"");
      for (std::string& line : report.TakeLines()) result.errors.push_back(std::move(line));
      return result;
    }
    top.AllowOnly({"format", "description", "problem", "parameters", "samples", "seed", "outputs"});
    if (!format || *format != "cosserat-study/1")
      report.Expected("format", "\"cosserat-study/1\"", format ? detail::Describe(*format) : "nothing");
    detail::ReadString(top, "description", Presence::kOptional);
    ReadProblem(top, base_directory, &study);
    study.samples =
        detail::ReadInteger(top, "samples", 1, static_cast<int>(kMaxStudyPoints), Presence::kOptional)
            .value_or(1);
    study.seed = static_cast<std::uint64_t>(
        detail::ReadInteger(top, "seed", 0, 2147483647, Presence::kOptional).value_or(1));
    const json* params = top.Find("parameters");
    if (!params || !params->is_array()) {
      report.Expected("parameters", "an array of parameters",
                      params ? detail::Describe(*params) : "nothing");
    } else {
      for (std::size_t i = 0; i < params->size(); ++i) {
        const std::string where = detail::ElementPath("parameters", i);
        if (!(*params)[i].is_object()) {
          report.Expected(where, "an object", detail::Describe((*params)[i]));
          continue;
        }
        StudyParameter p;
        ParseParameter(ObjectReader((*params)[i], where, &report), &p);
        const json* path = (*params)[i].contains("path") ? &(*params)[i]["path"] : nullptr;
        if (path && path->is_string() && study.problem.is_object())
          CheckPath(study.problem, where + ".path", p.path, &report);
        CheckPlaceApart(study.parameters, p.path, where + ".path", &report);
        study.parameters.push_back(p);
      }
    }
    ReadOutputs(top, &study);
    if (report.empty() && study.PointCount() > kMaxStudyPoints)
      report.Expected("parameters",
                      "at most " + std::to_string(kMaxStudyPoints) +
                          " points in all (samples × the grids' counts; the sweep keeps each "
                          "point's row in memory)",
                      std::to_string(study.PointCount()) + " points");
  }
  if (report.empty() && result.errors.empty()) CheckPointsMakeProblems(study, &report);
  for (std::string& line : report.TakeLines()) result.errors.push_back(std::move(line));
  if (result.errors.empty()) result.study = std::move(study);
  return result;
}

std::string PointWords(const Study& study, std::uint64_t k) {
  const std::vector<double> values = study.Point(k);
  std::string words;
  for (std::size_t j = 0; j < values.size(); ++j)  // as the CSV writes them
    words += (j ? ", " : "") + study.parameters[j].path + " = " + detail::ShortestNumber(values[j]);
  return words;
}

StudyPointCheck CheckStudyPoints(const Study& study, std::uint64_t limit) {
  StudyPointCheck check;
  check.checked = std::min(limit, study.PointCount());
  for (std::uint64_t k = 0; k < check.checked; ++k) {
    const ParseResult point = ParseProblemDocument(study.PointProblem(k));
    if (point.errors.empty()) continue;
    if (check.invalid++ == 0) {
      check.first = k;
      check.first_error = point.errors.front();
    }
  }
  return check;
}

StudyParseResult LoadStudyFile(const std::string& path) {
  std::string text, why;
  if (!ReadTextFile(path, &text, &why)) {
    StudyParseResult r;
    r.errors.push_back(path + ": cannot read the file (" + why + ")");
    return r;
  }
  const std::string dir = std::filesystem::path(path).parent_path().string();
  return ParseStudy(text, path, dir.empty() ? "." : dir);
}

}  // namespace cosserat::io

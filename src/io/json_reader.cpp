#include "cosserat/io/json_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <sstream>

#include "did_you_mean.hpp"

namespace cosserat::io::detail {
namespace {

using json = nlohmann::json;

const char* const kMatrix3Expected = "a 3x3 matrix (an array of 3 rows of 3 numbers)";

std::string Plural(std::size_t n, const char* noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

/// ` (did you mean "x"?)` when a candidate is close to `word`, else empty.
std::string DidYouMeanSuffix(const std::string& word, const std::vector<std::string>& candidates) {
  const auto match = ClosestMatch(word, candidates);
  return match ? " (did you mean " + Quote(*match) + "?)" : "";
}

/// The value at `key`, or nullptr; an absent required key is reported as missing.
const json* FindValue(const ObjectReader& o, const std::string& key, Presence presence,
                      const std::string& expected) {
  const json* v = o.Find(key);
  if (!v && presence == Presence::kRequired) o.report().Missing(o.PathOf(key), expected);
  return v;
}

/// Checks that `v` is an array of exactly 3 items, then each item with
/// `check_item(item, item_path, index)`, which reports its own errors and returns whether it
/// passed. Every item is checked, so each bad one is reported at its own index.
template <typename CheckItem>
bool CheckThreeItems(const json& v, const std::string& path, const std::string& expected,
                     ErrorReport& report, CheckItem check_item) {
  if (!v.is_array() || v.size() != 3) {
    report.Expected(path, expected, Describe(v));
    return false;
  }
  bool ok = true;
  for (std::size_t i = 0; i < 3; ++i)
    ok = check_item(v[i], ElementPath(path, i), static_cast<int>(i)) && ok;
  return ok;
}

}  // namespace

// --- Message text ------------------------------------------------------------------------------

std::string Describe(const json& v) {
  switch (v.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return v.get<bool>() ? "true" : "false";
    case json::value_t::number_float:
      if (!std::isfinite(v.get<double>())) return "a number too large for a double (overflow)";
      return v.dump();
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
      return v.dump();
    case json::value_t::string: {
      std::string text = v.dump();
      if (text.size() > 42) text = text.substr(0, 40) + "...\"";
      return "a string (" + text + ")";
    }
    case json::value_t::array:
      return v.empty() ? "an empty array" : "an array of " + Plural(v.size(), "item");
    case json::value_t::object:
      return v.empty() ? "an empty object" : "an object";
    default:
      return "a value of type " + std::string(v.type_name());
  }
}

std::string Quote(const std::string& text) { return json(text).dump(); }

std::string QuotedList(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : ", ") + Quote(w);
  return out;
}

std::string FormatNumber(double x) {
  std::ostringstream os;
  os << std::setprecision(6) << x;
  return os.str();
}

std::string ShortestNumber(double x) {
  char buf[32];
  for (int digits = 15; digits <= 17; ++digits) {  // the fewest that read back as x
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    if (std::strtod(buf, nullptr) == x) break;
  }
  return buf;
}

// --- Collecting errors -------------------------------------------------------------------------

namespace {

// A line's part echoed from the file, cut to about `limit` bytes (at the start of a UTF-8
// character, so that the line stays valid text): a key or a string of megabytes would otherwise
// come back whole on one line.
std::string Cut(const std::string& text, std::size_t limit) {
  if (text.size() <= limit) return text;
  std::size_t end = limit;
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;
  return text.substr(0, end) + "... (" + std::to_string(text.size() - end) + " more bytes)";
}

}  // namespace

void ErrorReport::Add(const std::string& path, const std::string& message) {
  lines_.push_back(Cut(ShownPath(path), 200) + ": " + Cut(message, 2000));
}

void ErrorReport::Expected(const std::string& path, const std::string& expected,
                           const std::string& found) {
  Add(path, "expected " + expected + ", got " + found);
}

void ErrorReport::Missing(const std::string& path, const std::string& expected) {
  Expected(path, expected, "nothing (required key is missing)");
}

// --- Objects -----------------------------------------------------------------------------------

ObjectReader::ObjectReader(const json& object, std::string path, ErrorReport* report)
    : object_(&object), path_(std::move(path)), report_(report) {}

void ObjectReader::AllowOnly(const std::vector<std::string>& allowed,
                             const std::string& context) const {
  const std::string where = context.empty() ? "" : " " + context;
  for (const auto& item : object_->items()) {
    if (std::find(allowed.begin(), allowed.end(), item.key()) != allowed.end()) continue;
    std::string hint = DidYouMeanSuffix(item.key(), allowed);
    if (hint.empty()) hint = " (allowed: " + QuotedList(allowed) + ")";
    report_->Add(PathOf(item.key()), "unknown key" + where + hint);
  }
}

const json* ObjectReader::Find(const std::string& key) const {
  const auto it = object_->find(key);
  return it == object_->end() ? nullptr : &*it;
}

void ObjectReader::Reject(const std::string& key, const std::string& expected) const {
  report_->Expected(PathOf(key), expected, Describe(*Find(key)));
}

// --- Typed reads -------------------------------------------------------------------------------

NumberRule AnyFiniteNumber() {
  return {"a finite number", [](double) { return true; }};
}
NumberRule PositiveNumber() {
  return {"a positive number", [](double x) { return x > 0; }};
}
NumberRule NonNegativeNumber() {
  return {"a number >= 0", [](double x) { return x >= 0; }};
}

std::optional<double> ReadNumber(const ObjectReader& o, const std::string& key,
                                 const NumberRule& rule, Presence presence) {
  const json* v = FindValue(o, key, presence, rule.expected);
  if (!v) return std::nullopt;
  return CheckNumber(*v, o.PathOf(key), rule, o.report());
}

std::optional<int> ReadInteger(const ObjectReader& o, const std::string& key, int min, int max,
                               Presence presence) {
  const std::string expected =
      "an integer between " + std::to_string(min) + " and " + std::to_string(max);
  const json* v = FindValue(o, key, presence, expected);
  if (!v) return std::nullopt;
  const double x = v->is_number() ? v->get<double>() : std::nan("");
  if (!std::isfinite(x) || x != std::floor(x) || x < min || x > max) {
    o.report().Expected(o.PathOf(key), expected, Describe(*v));
    return std::nullopt;
  }
  return static_cast<int>(x);
}

std::optional<std::string> ReadString(const ObjectReader& o, const std::string& key,
                                      Presence presence) {
  const json* v = FindValue(o, key, presence, "a string");
  if (!v) return std::nullopt;
  if (!v->is_string()) {
    o.report().Expected(o.PathOf(key), "a string", Describe(*v));
    return std::nullopt;
  }
  return v->get<std::string>();
}

std::optional<std::string> ReadChoice(const ObjectReader& o, const std::string& key,
                                      const std::vector<std::string>& choices, Presence presence) {
  const std::string expected = "one of " + QuotedList(choices);
  const json* v = FindValue(o, key, presence, expected);
  if (!v) return std::nullopt;
  if (!v->is_string()) {
    o.report().Expected(o.PathOf(key), expected, Describe(*v));
    return std::nullopt;
  }
  const std::string value = v->get<std::string>();
  if (std::find(choices.begin(), choices.end(), value) == choices.end()) {
    o.report().Expected(o.PathOf(key), expected, Quote(value) + DidYouMeanSuffix(value, choices));
    return std::nullopt;
  }
  return value;
}

std::optional<Vec3> ReadVec3(const ObjectReader& o, const std::string& key, Presence presence) {
  const std::string expected = "an array of 3 numbers";
  const json* v = FindValue(o, key, presence, expected);
  if (!v) return std::nullopt;
  return CheckVec3(*v, o.PathOf(key), expected, o.report());
}

std::optional<Vec3> ReadVec3(const ObjectReader& o, const std::string& key, Presence presence,
                             const NumberRule& rule) {
  const auto v = ReadVec3(o, key, presence);
  if (!v) return std::nullopt;
  bool ok = true;
  for (int i = 0; i < 3; ++i)
    if (!rule.accepts((*v)(i))) {
      o.report().Expected(ElementPath(o.PathOf(key), i), rule.expected, FormatNumber((*v)(i)));
      ok = false;
    }
  return ok ? v : std::nullopt;
}

std::optional<Mat3> ReadMatrix3(const ObjectReader& o, const std::string& key, Presence presence) {
  const json* v = FindValue(o, key, presence, kMatrix3Expected);
  if (!v) return std::nullopt;
  return CheckMatrix3(*v, o.PathOf(key), o.report());
}

std::optional<ObjectReader> ReadObject(const ObjectReader& parent, const std::string& key,
                                       Presence presence, const std::string& expected) {
  const json* v = FindValue(parent, key, presence, expected);
  if (!v) return std::nullopt;
  if (!v->is_object()) {
    parent.report().Expected(parent.PathOf(key), expected, Describe(*v));
    return std::nullopt;
  }
  return ObjectReader(*v, parent.PathOf(key), &parent.report());
}

// --- Checks of a value already in hand ----------------------------------------------------------

std::optional<double> CheckNumber(const json& v, const std::string& path, const NumberRule& rule,
                                  ErrorReport& report) {
  const double x = v.is_number() ? v.get<double>() : std::nan("");
  if (!std::isfinite(x) || !rule.accepts(x)) {
    report.Expected(path, rule.expected, Describe(v));
    return std::nullopt;
  }
  return x;
}

std::optional<Vec3> CheckVec3(const json& v, const std::string& path, const std::string& expected,
                              ErrorReport& report) {
  Vec3 out;
  auto check_number = [&](const json& item, const std::string& at, int i) {
    const auto x = CheckNumber(item, at, AnyFiniteNumber(), report);
    if (x) out(i) = *x;
    return x.has_value();
  };
  if (!CheckThreeItems(v, path, expected, report, check_number)) return std::nullopt;
  return out;
}

std::optional<Mat3> CheckMatrix3(const json& v, const std::string& path, ErrorReport& report) {
  Mat3 out;
  auto check_row = [&](const json& item, const std::string& at, int i) {
    const auto row = CheckVec3(item, at, "a row of 3 numbers", report);
    if (row) out.row(i) = row->transpose();
    return row.has_value();
  };
  if (!CheckThreeItems(v, path, kMatrix3Expected, report, check_row)) return std::nullopt;
  return out;
}

}  // namespace cosserat::io::detail

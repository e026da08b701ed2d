#include "cosserat/io/problem.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <utility>

namespace cosserat::io {
namespace {

using json = nlohmann::json;

constexpr int kMaxNodes = 1000000;
constexpr int kMaxIterations = 1000000;
constexpr int kMaxModes = 1000;
constexpr double kRotationTolerance = 1e-6;
/// Overflowing numbers recovered from (each costs a re-parse); beyond this the parse stops.
constexpr std::size_t kMaxOverflowRetries = 64;

// ---------------------------------------------------------------------------------------------
// JSON paths and the text of messages
// ---------------------------------------------------------------------------------------------

bool IsPlainKey(const std::string& key) {
  return !key.empty() && std::all_of(key.begin(), key.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '_' || c == '-';
  });
}

/// `rod` + `length` -> `rod.length`; keys that are not identifiers are quoted: `rod["a b"]`.
std::string ChildPath(const std::string& parent, const std::string& key) {
  if (!IsPlainKey(key)) return parent + "[" + json(key).dump() + "]";
  return parent.empty() ? key : parent + "." + key;
}

std::string ElementPath(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

std::string ShownPath(const std::string& path) { return path.empty() ? "(top level)" : path; }

std::string Quote(const std::string& text) { return json(text).dump(); }

std::string QuotedList(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : ", ") + Quote(w);
  return out;
}

/// A computed number (not echoed from the file), six significant digits.
std::string FormatNumber(double x) {
  std::ostringstream os;
  os << std::setprecision(6) << x;
  return os.str();
}

std::string Plural(std::size_t n, const char* noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

/// What a JSON value is, for the "got ..." half of a message.
std::string Describe(const json& v) {
  switch (v.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return v.get<bool>() ? "true" : "false";
    case json::value_t::number_float:
      if (!std::isfinite(v.get<double>())) return "a number too large for a double (overflow)";
      return v.dump();
    case json::value_t::number_integer:
    case json::value_t::number_unsigned: return v.dump();
    case json::value_t::string: {
      std::string text = v.dump();
      if (text.size() > 42) text = text.substr(0, 40) + "...\"";
      return "a string (" + text + ")";
    }
    case json::value_t::array:
      return v.empty() ? "an empty array" : "an array of " + Plural(v.size(), "item");
    case json::value_t::object: return v.empty() ? "an empty object" : "an object";
    default: return "a value of type " + std::string(v.type_name());
  }
}

// ---------------------------------------------------------------------------------------------
// Did-you-mean suggestions
// ---------------------------------------------------------------------------------------------

std::string Lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

/// The candidate matching `word` ignoring case, else the closest within edit distance 2 (and
/// shorter than the candidate itself, so one-letter keys do not match everything).
std::optional<std::string> Suggest(const std::string& word,
                                   const std::vector<std::string>& candidates) {
  for (const std::string& c : candidates)
    if (Lower(c) == Lower(word)) return c;
  std::optional<std::string> best;
  std::size_t best_distance = 3;
  for (const std::string& c : candidates) {
    const std::size_t d = EditDistance(word, c);
    if (d < best_distance && d < c.size()) best = c, best_distance = d;
  }
  return best;
}

std::string SuggestionSuffix(const std::string& word, const std::vector<std::string>& candidates) {
  const auto s = Suggest(word, candidates);
  return s ? " (did you mean " + Quote(*s) + "?)" : "";
}

// ---------------------------------------------------------------------------------------------
// JSON text -> document. A SAX handler builds the document while tracking the JSON path, so that
// duplicate keys and numbers overflowing a double can be reported where they are.
// ---------------------------------------------------------------------------------------------

class DocumentBuilder final : public json::json_sax_t {
 public:
  struct Failure {
    int id = 0;                ///< nlohmann exception id: 101.. syntax, 406 number overflow
    std::size_t position = 0;  ///< bytes read when it failed
    std::string token;         ///< the offending token
    std::string path;          ///< where the value being read would have gone
    std::string message;       ///< the parser's own message
  };

  /// `overflowed`: paths whose number overflowed in an earlier pass (the token was blanked to 0);
  /// they get ±infinity so that validation reports them.
  explicit DocumentBuilder(const std::map<std::string, double>* overflowed)
      : overflowed_(overflowed) {}

  json TakeDocument() { return std::move(document_); }
  const std::optional<Failure>& failure() const { return failure_; }
  const std::vector<std::string>& duplicate_keys() const { return duplicate_keys_; }

  bool null() override { return Add(nullptr); }
  bool boolean(bool value) override { return Add(value); }
  bool number_integer(number_integer_t value) override { return Add(value); }
  bool number_unsigned(number_unsigned_t value) override { return Add(value); }
  bool number_float(number_float_t value, const string_t&) override { return Add(value); }
  bool string(string_t& value) override { return Add(std::move(value)); }
  bool binary(binary_t& value) override { return Add(json::binary(std::move(value))); }
  bool start_object(std::size_t) override { return Open(json::object()); }
  bool start_array(std::size_t) override { return Open(json::array()); }
  bool end_object() override { return Close(); }
  bool end_array() override { return Close(); }

  bool key(string_t& key) override {
    Frame& top = stack_.back();
    if (top.container->contains(key))
      duplicate_keys_.push_back(ChildPath(top.path, key));
    top.key = key;
    return true;
  }

  bool parse_error(std::size_t position, const std::string& last_token,
                   const nlohmann::detail::exception& ex) override {
    failure_ = Failure{ex.id, position, last_token, NextPath(), ex.what()};
    return false;
  }

 private:
  struct Frame {
    json* container;
    std::string path;
    std::string key;  ///< the key being filled, for objects
  };

  std::string NextPath() const {
    if (stack_.empty()) return "";
    const Frame& top = stack_.back();
    return top.container->is_array() ? ElementPath(top.path, top.container->size())
                                     : ChildPath(top.path, top.key);
  }

  json* Place(json value, const std::string& path) {
    const auto it = overflowed_->find(path);
    if (it != overflowed_->end()) value = it->second;
    if (stack_.empty()) {
      document_ = std::move(value);
      return &document_;
    }
    json& container = *stack_.back().container;
    if (container.is_array()) {
      container.push_back(std::move(value));
      return &container.back();
    }
    json& slot = container[stack_.back().key];
    slot = std::move(value);
    return &slot;
  }

  bool Add(json value) {
    Place(std::move(value), NextPath());
    return true;
  }

  bool Open(json empty_container) {
    const std::string path = NextPath();
    json* placed = Place(std::move(empty_container), path);
    stack_.push_back({placed, path, ""});
    return true;
  }

  bool Close() {
    stack_.pop_back();
    return true;
  }

  const std::map<std::string, double>* overflowed_;
  json document_;
  std::vector<Frame> stack_;
  std::vector<std::string> duplicate_keys_;
  std::optional<Failure> failure_;
};

/// Replaces the overflowing number token that ends at `end` by "0" and blanks, keeping every
/// later byte (and so every later line and column) in place.
bool BlankToken(std::string* text, std::size_t end, const std::string& token) {
  if (token.empty() || end < token.size()) return false;
  const std::size_t start = end - token.size();
  if (text->compare(start, token.size(), token) != 0) return false;
  text->replace(start, token.size(), "0" + std::string(token.size() - 1, ' '));
  return true;
}

/// "[json.exception.parse_error.101] parse error at line 3, column 5: syntax error ..." ->
/// "at line 3, column 5: syntax error ...".
std::string SyntaxErrorText(const DocumentBuilder::Failure& failure, const std::string& text) {
  const std::size_t at = failure.message.find("at line ");
  if (at != std::string::npos) return failure.message.substr(at);
  // Fall back to counting lines ourselves.
  const std::size_t end = std::min(failure.position, text.size());
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') ++line, column = 1;
    else ++column;
  }
  const std::size_t bracket = failure.message.find("] ");
  const std::string what =
      bracket == std::string::npos ? failure.message : failure.message.substr(bracket + 2);
  return "at line " + std::to_string(line) + ", column " + std::to_string(column) + ": " + what;
}

struct Document {
  std::optional<json> value;
  std::vector<std::string> errors;
};

Document ReadDocument(const std::string& text, const std::string& source_name) {
  std::string work = text;
  std::map<std::string, double> overflowed;
  // Each pass either succeeds, fails for good, or blanks one overflowing number and retries.
  for (;;) {
    DocumentBuilder builder(&overflowed);
    if (json::sax_parse(work, &builder)) {
      Document doc{builder.TakeDocument(), {}};
      for (const std::string& path : builder.duplicate_keys())
        doc.errors.push_back(ShownPath(path) +
                             ": expected each key once in an object, got a duplicate key");
      return doc;
    }
    const DocumentBuilder::Failure failure = builder.failure().value_or(DocumentBuilder::Failure{});
    const bool overflow = failure.id == 406 && overflowed.size() < kMaxOverflowRetries;
    if (overflow && !overflowed.count(failure.path) &&
        BlankToken(&work, failure.position, failure.token)) {
      const double inf = std::numeric_limits<double>::infinity();
      overflowed[failure.path] = failure.token[0] == '-' ? -inf : inf;
      continue;
    }
    return {std::nullopt, {source_name + ": invalid JSON " + SyntaxErrorText(failure, text)}};
  }
}

// ---------------------------------------------------------------------------------------------
// Collecting errors, and typed reads of JSON values
// ---------------------------------------------------------------------------------------------

class Report {
 public:
  void Add(const std::string& path, const std::string& message) {
    lines_.push_back(ShownPath(path) + ": " + message);
  }
  void Expected(const std::string& path, const std::string& expected, const std::string& found) {
    Add(path, "expected " + expected + ", got " + found);
  }
  void Missing(const std::string& path, const std::string& expected) {
    Expected(path, expected, "nothing (required key is missing)");
  }
  bool empty() const { return lines_.empty(); }
  std::vector<std::string> TakeLines() { return std::move(lines_); }

 private:
  std::vector<std::string> lines_;
};

/// A JSON object at a path; looks keys up and reports the ones it does not know.
class Object {
 public:
  Object(const json& value, std::string path, Report* report)
      : value_(&value), path_(std::move(path)), report_(report) {}

  /// Reports every key not in `allowed`: with a suggestion if one is close, else the list.
  /// `context` qualifies the message, e.g. `for a "circle" section`.
  void AllowOnly(const std::vector<std::string>& allowed, const std::string& context = "") const {
    for (const auto& item : value_->items()) {
      if (std::find(allowed.begin(), allowed.end(), item.key()) != allowed.end()) continue;
      const std::string where = context.empty() ? "" : " " + context;
      const auto suggestion = Suggest(item.key(), allowed);
      report_->Add(PathOf(item.key()),
                   "unknown key" + where +
                       (suggestion ? " (did you mean " + Quote(*suggestion) + "?)"
                                   : " (allowed: " + QuotedList(allowed) + ")"));
    }
  }

  const json* Find(const std::string& key) const {
    const auto it = value_->find(key);
    return it == value_->end() ? nullptr : &*it;
  }
  bool Has(const std::string& key) const { return Find(key) != nullptr; }
  std::string PathOf(const std::string& key) const { return ChildPath(path_, key); }
  const std::string& path() const { return path_; }
  Report& report() const { return *report_; }

 private:
  const json* value_;
  std::string path_;
  Report* report_;
};

enum class Need { kOptional, kRequired };

struct NumberRule {
  std::string expected;
  std::function<bool(double)> accepts;
};

NumberRule AnyNumber() {
  return {"a finite number", [](double) { return true; }};
}
NumberRule PositiveNumber() {
  return {"a positive number", [](double x) { return x > 0; }};
}
NumberRule NonNegativeNumber() {
  return {"a number >= 0", [](double x) { return x >= 0; }};
}

std::optional<double> CheckNumber(const json& v, const std::string& path, const NumberRule& rule,
                                  Report& report) {
  if (!v.is_number()) {
    report.Expected(path, rule.expected, Describe(v));
    return std::nullopt;
  }
  const double x = v.get<double>();
  if (!std::isfinite(x) || !rule.accepts(x)) {
    report.Expected(path, rule.expected, Describe(v));
    return std::nullopt;
  }
  return x;
}

std::optional<double> ReadNumber(const Object& o, const std::string& key, const NumberRule& rule,
                                 Need need) {
  const json* v = o.Find(key);
  if (!v) {
    if (need == Need::kRequired) o.report().Missing(o.PathOf(key), rule.expected);
    return std::nullopt;
  }
  return CheckNumber(*v, o.PathOf(key), rule, o.report());
}

/// An integer in [min, max]; 41.0 counts as an integer, 41.5 does not.
std::optional<int> ReadInteger(const Object& o, const std::string& key, int min, int max,
                               Need need) {
  const std::string expected = "an integer between " + std::to_string(min) + " and " +
                               std::to_string(max);
  const json* v = o.Find(key);
  if (!v) {
    if (need == Need::kRequired) o.report().Missing(o.PathOf(key), expected);
    return std::nullopt;
  }
  const double x = v->is_number() ? v->get<double>() : std::nan("");
  if (!std::isfinite(x) || x != std::floor(x) || x < min || x > max) {
    o.report().Expected(o.PathOf(key), expected, Describe(*v));
    return std::nullopt;
  }
  return static_cast<int>(x);
}

std::optional<std::string> ReadString(const Object& o, const std::string& key, Need need) {
  const json* v = o.Find(key);
  if (!v) {
    if (need == Need::kRequired) o.report().Missing(o.PathOf(key), "a string");
    return std::nullopt;
  }
  if (!v->is_string()) {
    o.report().Expected(o.PathOf(key), "a string", Describe(*v));
    return std::nullopt;
  }
  return v->get<std::string>();
}

/// One of a fixed list of strings (an enumeration).
std::optional<std::string> ReadChoice(const Object& o, const std::string& key,
                                      const std::vector<std::string>& choices, Need need) {
  const std::string expected = "one of " + QuotedList(choices);
  const json* v = o.Find(key);
  if (!v) {
    if (need == Need::kRequired) o.report().Missing(o.PathOf(key), expected);
    return std::nullopt;
  }
  if (!v->is_string()) {
    o.report().Expected(o.PathOf(key), expected, Describe(*v));
    return std::nullopt;
  }
  const std::string value = v->get<std::string>();
  if (std::find(choices.begin(), choices.end(), value) == choices.end()) {
    o.report().Expected(o.PathOf(key), expected, Quote(value) + SuggestionSuffix(value, choices));
    return std::nullopt;
  }
  return value;
}

/// An array of exactly 3 numbers; each bad element is reported at its own index.
std::optional<Vec3> CheckVec3(const json& v, const std::string& path, const std::string& expected,
                              Report& report) {
  if (!v.is_array() || v.size() != 3) {
    report.Expected(path, expected, Describe(v));
    return std::nullopt;
  }
  Vec3 out;
  bool ok = true;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto x = CheckNumber(v[i], ElementPath(path, i), AnyNumber(), report);
    ok = ok && x.has_value();
    out(static_cast<int>(i)) = x.value_or(0.0);
  }
  if (!ok) return std::nullopt;
  return out;
}

std::optional<Vec3> ReadVec3(const Object& o, const std::string& key, Need need) {
  const std::string expected = "an array of 3 numbers";
  const json* v = o.Find(key);
  if (!v) {
    if (need == Need::kRequired) o.report().Missing(o.PathOf(key), expected);
    return std::nullopt;
  }
  return CheckVec3(*v, o.PathOf(key), expected, o.report());
}

/// Row-major 3×3: an array of 3 rows of 3 numbers.
std::optional<Mat3> CheckMatrix3(const json& v, const std::string& path, Report& report) {
  if (!v.is_array() || v.size() != 3) {
    report.Expected(path, "a 3x3 matrix (an array of 3 rows of 3 numbers)", Describe(v));
    return std::nullopt;
  }
  Mat3 out;
  bool ok = true;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto row = CheckVec3(v[i], ElementPath(path, i), "a row of 3 numbers", report);
    ok = ok && row.has_value();
    if (row) out.row(static_cast<int>(i)) = row->transpose();
  }
  if (!ok) return std::nullopt;
  return out;
}

std::optional<Object> ReadObject(const Object& parent, const std::string& key, Need need,
                                 const std::string& expected = "an object") {
  const json* v = parent.Find(key);
  if (!v) {
    if (need == Need::kRequired) parent.report().Missing(parent.PathOf(key), expected);
    return std::nullopt;
  }
  if (!v->is_object()) {
    parent.report().Expected(parent.PathOf(key), expected, Describe(*v));
    return std::nullopt;
  }
  return Object(*v, parent.PathOf(key), &parent.report());
}

// ---------------------------------------------------------------------------------------------
// rod.section
// ---------------------------------------------------------------------------------------------

struct ShapeKeys {
  std::string shape;
  std::vector<std::string> keys;  ///< besides "shape"
};

const std::vector<ShapeKeys>& SectionShapes() {
  static const std::vector<ShapeKeys> shapes = {
      {"circle", {"radius"}},
      {"annulus", {"outer_radius", "inner_radius"}},
      {"rectangle", {"width", "height"}},
      {"explicit", {"area", "I1", "I2", "J", "shear_coefficient"}},
  };
  return shapes;
}

std::vector<std::string> SectionKeys(const std::optional<std::string>& shape) {
  std::vector<std::string> keys{"shape"};
  for (const ShapeKeys& s : SectionShapes())
    if (!shape || s.shape == *shape) keys.insert(keys.end(), s.keys.begin(), s.keys.end());
  return keys;
}

std::vector<std::string> SectionShapeNames() {
  std::vector<std::string> names;
  for (const ShapeKeys& s : SectionShapes()) names.push_back(s.shape);
  return names;
}

/// "shape" if given; a section without one is explicit when it names any explicit property.
std::optional<std::string> SectionShape(const Object& s) {
  if (s.Has("shape")) return ReadChoice(s, "shape", SectionShapeNames(), Need::kRequired);
  for (const char* key : {"area", "I1", "I2", "J"})
    if (s.Has(key)) return std::string("explicit");
  s.report().Missing(s.PathOf("shape"),
                     "one of " + QuotedList(SectionShapeNames()) +
                         " (or the explicit properties \"area\", \"I1\", \"I2\", \"J\")");
  return std::nullopt;
}

std::optional<CrossSection> ParseAnnulus(const Object& s) {
  const auto outer = ReadNumber(s, "outer_radius", PositiveNumber(), Need::kRequired);
  const auto inner = ReadNumber(s, "inner_radius", NonNegativeNumber(), Need::kRequired);
  if (!outer || !inner) return std::nullopt;
  if (*inner >= *outer) {
    s.report().Expected(s.PathOf("inner_radius"),
                        "a number smaller than outer_radius (" + FormatNumber(*outer) + ")",
                        Describe(*s.Find("inner_radius")));
    return std::nullopt;
  }
  return CrossSection::Annulus(*outer, *inner);
}

std::optional<CrossSection> ParseExplicitSection(const Object& s) {
  const auto area = ReadNumber(s, "area", PositiveNumber(), Need::kRequired);
  const auto I1 = ReadNumber(s, "I1", PositiveNumber(), Need::kRequired);
  const auto I2 = ReadNumber(s, "I2", PositiveNumber(), Need::kRequired);
  const auto J = ReadNumber(s, "J", PositiveNumber(), Need::kRequired);
  const auto kappa = ReadNumber(s, "shear_coefficient", PositiveNumber(), Need::kOptional);
  if (!area || !I1 || !I2 || !J || (s.Has("shear_coefficient") && !kappa)) return std::nullopt;
  return CrossSection::Explicit(*area, *I1, *I2, *J, kappa.value_or(1.0));
}

std::optional<CrossSection> ParseSection(const Object& s) {
  const std::optional<std::string> shape = SectionShape(s);
  if (!shape) {
    s.AllowOnly(SectionKeys(std::nullopt));
    return std::nullopt;
  }
  s.AllowOnly(SectionKeys(shape), "for a " + Quote(*shape) + " section");
  if (*shape == "circle") {
    const auto r = ReadNumber(s, "radius", PositiveNumber(), Need::kRequired);
    if (!r) return std::nullopt;
    return CrossSection::Circle(*r);
  }
  if (*shape == "annulus") return ParseAnnulus(s);
  if (*shape == "rectangle") {
    const auto w = ReadNumber(s, "width", PositiveNumber(), Need::kRequired);
    const auto h = ReadNumber(s, "height", PositiveNumber(), Need::kRequired);
    if (!w || !h) return std::nullopt;
    return CrossSection::Rectangle(*w, *h);
  }
  return ParseExplicitSection(s);
}

// ---------------------------------------------------------------------------------------------
// rod.material
// ---------------------------------------------------------------------------------------------

std::optional<KelvinVoigtDamping> ParseDamping(const Object& d) {
  d.AllowOnly({"bending", "torsion", "shear", "extension"});
  KelvinVoigtDamping out;
  bool ok = true;
  auto read = [&](const char* key, double* target) {
    const auto x = ReadNumber(d, key, NonNegativeNumber(), Need::kOptional);
    if (x) *target = *x;
    ok = ok && (x || !d.Has(key));
  };
  read("bending", &out.bending);
  read("torsion", &out.torsion);
  read("shear", &out.shear);
  read("extension", &out.extension);
  if (!ok) return std::nullopt;
  return out;
}

/// The shear modulus, from "shear_modulus" or "poisson_ratio" (exactly one must be given).
std::optional<double> ParseShearModulus(const Object& m, std::optional<double> E) {
  const bool has_G = m.Has("shear_modulus"), has_nu = m.Has("poisson_ratio");
  if (has_G == has_nu) {
    m.report().Expected(m.path(), R"(exactly one of "shear_modulus" and "poisson_ratio")",
                        has_G ? "both" : "neither");
  }
  const NumberRule poisson{"a number in (-1, 0.5]", [](double nu) { return nu > -1 && nu <= 0.5; }};
  const auto G = has_G ? ReadNumber(m, "shear_modulus", PositiveNumber(), Need::kOptional)
                       : std::nullopt;
  const auto nu = has_nu ? ReadNumber(m, "poisson_ratio", poisson, Need::kOptional)
                         : std::nullopt;
  if (has_G == has_nu || !E) return std::nullopt;
  if (has_nu) {
    if (!nu) return std::nullopt;
    return *E / (2.0 * (1.0 + *nu));
  }
  if (!G) return std::nullopt;
  const double implied_nu = *E / (2.0 * *G) - 1.0;
  if (implied_nu > 0.5 + 1e-12) {
    m.report().Expected(m.PathOf("shear_modulus"),
                        "at least youngs_modulus / 3 = " + FormatNumber(*E / 3.0) +
                            " (a Poisson ratio <= 0.5)",
                        Describe(*m.Find("shear_modulus")) + " (Poisson ratio " +
                            FormatNumber(implied_nu) + ")");
    return std::nullopt;
  }
  return *G;
}

std::optional<Material> ParseMaterial(const Object& m) {
  m.AllowOnly({"youngs_modulus", "shear_modulus", "poisson_ratio", "density", "damping"});
  const auto E = ReadNumber(m, "youngs_modulus", PositiveNumber(), Need::kRequired);
  const auto G = ParseShearModulus(m, E);
  const auto rho = ReadNumber(m, "density", NonNegativeNumber(), Need::kRequired);
  std::optional<KelvinVoigtDamping> damping = KelvinVoigtDamping{};
  if (m.Has("damping")) {
    const auto d = ReadObject(m, "damping", Need::kOptional);
    damping = d ? ParseDamping(*d) : std::nullopt;
  }
  if (!E || !G || !rho || !damping) return std::nullopt;
  Material out = Material::FromShearModulus(*E, *G, *rho);
  out.damping = *damping;
  return out;
}

// ---------------------------------------------------------------------------------------------
// rod.stiffness_profile
// ---------------------------------------------------------------------------------------------

using Band = BandedSection::Band;

std::optional<Band> ParseBand(const Object& b, std::optional<double> length) {
  b.AllowOnly({"start", "end", "factor"});
  const auto start = ReadNumber(b, "start", NonNegativeNumber(), Need::kRequired);
  const auto end = ReadNumber(b, "end", PositiveNumber(), Need::kRequired);
  const auto factor = ReadNumber(b, "factor", PositiveNumber(), Need::kRequired);
  if (!start || !end || !factor) return std::nullopt;
  if (*end <= *start) {
    b.report().Expected(b.PathOf("end"), "a number greater than start (" + FormatNumber(*start) + ")",
                        Describe(*b.Find("end")));
    return std::nullopt;
  }
  if (length && *end > *length) {
    b.report().Expected(b.PathOf("end"), "a number <= rod.length (" + FormatNumber(*length) + ")",
                        Describe(*b.Find("end")));
    return std::nullopt;
  }
  return Band{*start, *end, *factor};
}

/// Bands of scaled bending and torsion stiffness; nullopt if any is invalid.
std::optional<std::vector<Band>> ParseStiffnessProfile(const Object& rod,
                                                       std::optional<double> length) {
  const char* expected = R"(an array of bands {"start", "end", "factor"})";
  const json* v = rod.Find("stiffness_profile");
  if (!v) return std::vector<Band>{};
  const std::string path = rod.PathOf("stiffness_profile");
  if (!v->is_array()) {
    rod.report().Expected(path, expected, Describe(*v));
    return std::nullopt;
  }
  std::vector<Band> bands;
  bool ok = true;
  for (std::size_t i = 0; i < v->size(); ++i) {
    const std::string at = ElementPath(path, i);
    if (!(*v)[i].is_object()) {
      rod.report().Expected(at, R"(a band {"start", "end", "factor"})", Describe((*v)[i]));
      ok = false;
      continue;
    }
    const auto band = ParseBand(Object((*v)[i], at, &rod.report()), length);
    ok = ok && band.has_value();
    if (band) bands.push_back(*band);
  }
  if (!ok) return std::nullopt;
  return bands;
}

/// Band ends strictly inside (0, L), counted the way MakeGrid places nodes on them.
int InteriorBreakpoints(const std::vector<Band>& bands, double length) {
  std::vector<double> cuts;
  for (const Band& b : bands) cuts.insert(cuts.end(), {b.start, b.end});
  std::sort(cuts.begin(), cuts.end());
  const double eps = 1e-12 * length;
  double last = 0.0;
  int count = 0;
  for (double c : cuts)
    if (c > eps && c < length - eps && c - last > eps) last = c, ++count;
  return count;
}

// ---------------------------------------------------------------------------------------------
// rod, base, loads, solver
// ---------------------------------------------------------------------------------------------

void ParseRod(const Object& rod, Problem* problem) {
  rod.AllowOnly(
      {"length", "nodes", "section", "material", "rest_curvature", "stiffness_profile"});
  const auto length = ReadNumber(rod, "length", PositiveNumber(), Need::kRequired);
  const auto nodes = ReadInteger(rod, "nodes", 3, kMaxNodes, Need::kRequired);
  const auto section_object = ReadObject(rod, "section", Need::kRequired);
  const auto section = section_object ? ParseSection(*section_object) : std::nullopt;
  const auto material_object = ReadObject(rod, "material", Need::kRequired);
  const auto material = material_object ? ParseMaterial(*material_object) : std::nullopt;
  const auto rest_curvature = ReadVec3(rod, "rest_curvature", Need::kOptional);
  const auto bands = ParseStiffnessProfile(rod, length);

  if (nodes && length && bands) {
    const int needed = 2 + InteriorBreakpoints(*bands, *length);
    if (*nodes < needed)
      rod.report().Expected(rod.PathOf("nodes"),
                            "at least " + std::to_string(needed) +
                                " (a node at each end and at every stiffness_profile band end "
                                "inside the rod)",
                            Describe(*rod.Find("nodes")));
  }
  if (length && section && material && bands) {
    problem->rod = RodModel::Uniform(*length, *section, *material);
    if (!bands->empty())
      problem->rod.section = std::make_shared<BandedSection>(problem->rod.section, *bands);
  }
  if (rest_curvature) problem->rod.rest_strain = ConstantRestCurvature(*rest_curvature);
  problem->nodes = nodes.value_or(problem->nodes);
}

/// The rotation nearest to M (polar decomposition), so a matrix accepted within the tolerance
/// reaches the solver exactly orthonormal.
Mat3 NearestRotation(const Mat3& M) {
  Eigen::JacobiSVD<Mat3> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return svd.matrixU() * svd.matrixV().transpose();
}

std::optional<Mat3> ReadRotation(const Object& o, const std::string& key) {
  const json* v = o.Find(key);
  if (!v) return std::nullopt;
  const auto M = CheckMatrix3(*v, o.PathOf(key), o.report());
  if (!M) return std::nullopt;
  const double orthogonality = (M->transpose() * *M - Mat3::Identity()).cwiseAbs().maxCoeff();
  const double det = M->determinant();
  if (!(orthogonality <= kRotationTolerance && det > 0)) {
    o.report().Expected(o.PathOf(key),
                        "a rotation matrix (orthonormal within 1e-6, i.e. max |R^T R - I| <= "
                        "1e-6, with determinant +1)",
                        "max |R^T R - I| = " + FormatNumber(orthogonality) +
                            " and determinant " + FormatNumber(det));
    return std::nullopt;
  }
  return NearestRotation(*M);
}

void ParseBase(const Object& base, lie::SE3* pose) {
  base.AllowOnly({"position", "rotation"});
  pose->p = ReadVec3(base, "position", Need::kOptional).value_or(Vec3::Zero());
  pose->R = ReadRotation(base, "rotation").value_or(Mat3::Identity());
}

LoadFrame ReadFrame(const Object& o, const std::string& key) {
  const auto frame = ReadChoice(o, key, {"world", "body"}, Need::kOptional);
  return frame == std::optional<std::string>("body") ? LoadFrame::kBody : LoadFrame::kWorld;
}

StaticLoads ParseLoads(const Object& o) {
  o.AllowOnly({"gravity", "tip_force", "tip_force_frame", "tip_moment", "tip_moment_frame",
               "distributed_force"});
  StaticLoads loads;
  loads.gravity_W = ReadVec3(o, "gravity", Need::kOptional).value_or(Vec3::Zero());
  loads.tip_force = ReadVec3(o, "tip_force", Need::kOptional).value_or(Vec3::Zero());
  loads.tip_force_frame = ReadFrame(o, "tip_force_frame");
  loads.tip_moment = ReadVec3(o, "tip_moment", Need::kOptional).value_or(Vec3::Zero());
  loads.tip_moment_frame = ReadFrame(o, "tip_moment_frame");
  loads.distributed_force_W =
      ReadVec3(o, "distributed_force", Need::kOptional).value_or(Vec3::Zero());
  return loads;
}

void ParseSolver(const Object& o, StaticShootingOptions* options) {
  o.AllowOnly({"tolerance", "max_iterations"});
  options->tolerance =
      ReadNumber(o, "tolerance", PositiveNumber(), Need::kOptional).value_or(options->tolerance);
  options->max_iterations = ReadInteger(o, "max_iterations", 1, kMaxIterations, Need::kOptional)
                                .value_or(options->max_iterations);
}

// ---------------------------------------------------------------------------------------------
// dynamics, buckling, modes (validated now, run by later versions)
// ---------------------------------------------------------------------------------------------

void ParseDynamics(const Object& o, Problem::Dynamics* d) {
  o.AllowOnly({"dt", "duration", "initial", "initial_loads"});
  const auto dt = ReadNumber(o, "dt", PositiveNumber(), Need::kOptional);
  const auto duration = ReadNumber(o, "duration", PositiveNumber(), Need::kOptional);
  d->dt = dt.value_or(d->dt);
  d->duration = duration.value_or(d->duration);
  const bool both_usable = (dt || !o.Has("dt")) && (duration || !o.Has("duration"));
  if (both_usable && d->dt > d->duration) {
    o.report().Expected(o.PathOf("dt"),
                        "a time step no longer than duration (" + FormatNumber(d->duration) +
                            " s)",
                        dt ? Describe(*o.Find("dt")) : FormatNumber(d->dt) + " (the default)");
  }
  d->initial = ReadChoice(o, "initial", {"static"}, Need::kOptional).value_or(d->initial);
  if (const auto loads = ReadObject(o, "initial_loads", Need::kOptional))
    d->initial_loads = ParseLoads(*loads);
}

void ParseBuckling(const Object& o, Problem::Buckling* b) {
  o.AllowOnly({"load", "direction", "max"});
  b->load = ReadChoice(o, "load", {"tip_force", "tip_moment", "gravity", "distributed_force"},
                       Need::kOptional)
                .value_or(b->load);
  if (const auto direction = ReadVec3(o, "direction", Need::kOptional)) {
    if (direction->norm() > 0)
      b->direction = direction->normalized();
    else
      o.report().Expected(o.PathOf("direction"), "a non-zero vector", "[0, 0, 0]");
  }
  b->max = ReadNumber(o, "max", PositiveNumber(), Need::kRequired).value_or(b->max);
}

void ParseModes(const Object& o, Problem::Modes* m) {
  o.AllowOnly({"count"});
  m->count = ReadInteger(o, "count", 1, kMaxModes, Need::kOptional).value_or(m->count);
}

// ---------------------------------------------------------------------------------------------
// The whole problem
// ---------------------------------------------------------------------------------------------

const std::vector<std::string> kAnalyses = {"statics", "dynamics", "buckling", "modes"};
const std::vector<std::string> kFormulations = {"se3-shooting", "quaternion-fd"};
const std::vector<std::string> kBoundaries = {"cantilever", "free-free", "pinned-pinned",
                                              "clamped-clamped", "clamped-pinned"};

void CheckFormat(const Object& top) {
  const std::string expected = Quote(kProblemFormat);
  const json* v = top.Find("format");
  if (!v)
    top.report().Missing("format", expected);
  else if (!v->is_string() || v->get<std::string>() != kProblemFormat)
    top.report().Expected("format", expected, Describe(*v));
}

void ParseTopLevel(const Object& top, Problem* p) {
  top.AllowOnly({"format", "description", "analysis", "formulation", "rod", "base", "boundary",
                 "loads", "dynamics", "buckling", "modes", "solver"});
  CheckFormat(top);
  ReadString(top, "description", Need::kOptional);
  p->analysis = ReadChoice(top, "analysis", kAnalyses, Need::kOptional).value_or(p->analysis);
  p->formulation =
      ReadChoice(top, "formulation", kFormulations, Need::kOptional).value_or(p->formulation);
  if (const auto rod = ReadObject(top, "rod", Need::kRequired)) ParseRod(*rod, p);
  if (const auto base = ReadObject(top, "base", Need::kOptional)) ParseBase(*base, &p->base);
  p->boundary = ReadChoice(top, "boundary", kBoundaries, Need::kOptional).value_or(p->boundary);
  if (const auto loads = ReadObject(top, "loads", Need::kOptional)) p->loads = ParseLoads(*loads);
  if (const auto o = ReadObject(top, "dynamics", Need::kOptional)) {
    p->has_dynamics = true;
    ParseDynamics(*o, &p->dynamics);
  }
  const auto buckling = ReadObject(top, "buckling",
                                   p->analysis == "buckling" ? Need::kRequired : Need::kOptional,
                                   R"(an object {"load", "direction", "max"})");
  if (buckling) {
    p->has_buckling = true;
    ParseBuckling(*buckling, &p->buckling);
  }
  if (const auto o = ReadObject(top, "modes", Need::kOptional)) {
    p->has_modes = true;
    ParseModes(*o, &p->modes);
  }
  if (const auto o = ReadObject(top, "solver", Need::kOptional)) ParseSolver(*o, &p->solver);
}

/// The library's own checks; they should never fire after the ones above.
void CheckWithLibrary(const Problem& p, Report* report) {
  std::string why;
  if (!p.rod.IsValid(&why)) report->Add("rod", why);
  if (!p.loads.IsValid(&why)) report->Add("loads", why);
  if (!p.solver.IsValid(&why)) report->Add("solver", why);
}

}  // namespace

ParseResult ParseProblem(const std::string& json_text, const std::string& source_name) {
  ParseResult result;
  Document doc = ReadDocument(json_text, source_name);
  result.errors = std::move(doc.errors);  // malformed JSON, or duplicate keys
  if (!doc.value) return result;
  Report report;
  if (!doc.value->is_object()) {
    report.Expected("", "an object", Describe(*doc.value));
  } else {
    Problem problem;
    ParseTopLevel(Object(*doc.value, "", &report), &problem);
    if (report.empty() && result.errors.empty()) CheckWithLibrary(problem, &report);
    if (report.empty() && result.errors.empty()) result.problem = std::move(problem);
  }
  for (std::string& line : report.TakeLines()) result.errors.push_back(std::move(line));
  return result;
}

ParseResult LoadProblemFile(const std::string& path) {
  auto unreadable = [&](const std::string& why) {
    ParseResult r;
    r.errors.push_back(path + ": cannot read the file (" + why + ")");
    return r;
  };
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return unreadable("it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) return unreadable(std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return unreadable("read error");
  return ParseProblem(text.str(), path);
}

std::vector<std::string> UnsupportedFeatures(const Problem& p) {
  std::vector<std::string> out;
  auto check = [&](const char* key, const std::string& value, const char* supported) {
    if (value != supported)
      out.push_back(std::string(key) + ": " + Quote(value) +
                    " is not implemented in this version (supported: " + Quote(supported) + ")");
  };
  check("analysis", p.analysis, "statics");
  check("formulation", p.formulation, "se3-shooting");
  check("boundary", p.boundary, "cantilever");
  return out;
}

}  // namespace cosserat::io

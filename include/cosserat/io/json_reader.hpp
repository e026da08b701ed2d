#pragma once
/// \file
/// Typed, validating reads from a parsed JSON document (see json_document.hpp) for the input-file
/// parsers. Every problem found becomes one line `<json.path>: expected <what>, got <found>` in an
/// ErrorReport, and reading goes on, so that one run reports every error in a file.

#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cosserat/io/json_path.hpp"
#include "cosserat/lie/types.hpp"

namespace cosserat::io::detail {

// --- Message text ------------------------------------------------------------------------------

/// What a JSON value is, for the "got ..." half of a message: `null`, `-3`, `a string ("abc")`,
/// `an array of 2 items`, `an object`, ... Long strings are cut short.
std::string Describe(const nlohmann::json& value);

/// `abc` -> `"abc"`, escaped as in JSON.
std::string Quote(const std::string& text);

/// `"a", "b", "c"`.
std::string QuotedList(const std::vector<std::string>& words);

/// A number the parser computed (not echoed from the file), with six significant digits.
std::string FormatNumber(double x);

/// x in the fewest of 15–17 significant digits that read back as x (0.000355971, not
/// 0.00035597100000000001): a study's CSV cells and the points its messages name.
std::string ShortestNumber(double x);

// --- Collecting errors -------------------------------------------------------------------------

/// The error lines of one parse, in the order found.
class ErrorReport {
 public:
  /// `<path>: <message>`.
  void Add(const std::string& path, const std::string& message);
  /// `<path>: expected <expected>, got <found>`.
  void Expected(const std::string& path, const std::string& expected, const std::string& found);
  /// `<path>: expected <expected>, got nothing (required key is missing)`.
  void Missing(const std::string& path, const std::string& expected);

  bool empty() const { return lines_.empty(); }
  std::vector<std::string> TakeLines() { return std::move(lines_); }

 private:
  std::vector<std::string> lines_;
};

// --- Objects -----------------------------------------------------------------------------------

/// A JSON object at a known path, with the report its errors go to. Does not own the value.
class ObjectReader {
 public:
  ObjectReader(const nlohmann::json& object, std::string path, ErrorReport* report);

  /// Reports every key not in `allowed`, with a did-you-mean if one is close, else the allowed
  /// list. `context` qualifies the message, e.g. `for a "circle" section`.
  void AllowOnly(const std::vector<std::string>& allowed, const std::string& context = "") const;

  /// The value at `key`, or nullptr.
  const nlohmann::json* Find(const std::string& key) const;
  bool Has(const std::string& key) const { return Find(key) != nullptr; }
  std::string PathOf(const std::string& key) const { return ChildPath(path_, key); }

  /// Reports the value at `key`, which must be present, as not the `expected` one: for checks
  /// that involve other keys, made after the typed read accepted it.
  void Reject(const std::string& key, const std::string& expected) const;

  const std::string& path() const { return path_; }
  const nlohmann::json& value() const { return *object_; }
  ErrorReport& report() const { return *report_; }

 private:
  const nlohmann::json* object_;
  std::string path_;
  ErrorReport* report_;
};

// --- Typed reads -------------------------------------------------------------------------------
// Each returns the value, or nullopt when the key is absent or its value is reported as wrong.
// An absent key is an error only when it is Presence::kRequired.

enum class Presence { kOptional, kRequired };

/// Which finite numbers a read accepts, and how the message names them.
struct NumberRule {
  std::string expected;  ///< e.g. "a positive number"
  std::function<bool(double)> accepts;
};
NumberRule AnyFiniteNumber();
NumberRule PositiveNumber();
NumberRule NonNegativeNumber();

std::optional<double> ReadNumber(const ObjectReader& o, const std::string& key,
                                 const NumberRule& rule, Presence presence);

/// An integer in [min, max]; 41.0 counts as an integer, 41.5 does not.
std::optional<int> ReadInteger(const ObjectReader& o, const std::string& key, int min, int max,
                               Presence presence);

std::optional<std::string> ReadString(const ObjectReader& o, const std::string& key,
                                      Presence presence);

/// One of a fixed list of strings (an enumeration); a near miss gets a did-you-mean.
std::optional<std::string> ReadChoice(const ObjectReader& o, const std::string& key,
                                      const std::vector<std::string>& choices, Presence presence);

/// An array of exactly 3 numbers.
std::optional<Vec3> ReadVec3(const ObjectReader& o, const std::string& key, Presence presence);
/// A [x, y, z] whose entries all satisfy `rule` (each bad one reported at key[i]).
std::optional<Vec3> ReadVec3(const ObjectReader& o, const std::string& key, Presence presence,
                             const NumberRule& rule);

/// Row-major 3x3: an array of 3 rows of 3 numbers.
std::optional<Mat3> ReadMatrix3(const ObjectReader& o, const std::string& key, Presence presence);

/// A nested object; `expected` names it in messages (e.g. with its keys).
std::optional<ObjectReader> ReadObject(const ObjectReader& parent, const std::string& key,
                                       Presence presence,
                                       const std::string& expected = "an object");

// --- Checks of a value already in hand (e.g. an array element) at `path` -------------------------

std::optional<double> CheckNumber(const nlohmann::json& value, const std::string& path,
                                  const NumberRule& rule, ErrorReport& report);

/// An array of exactly 3 numbers; each bad element is reported at its own index.
std::optional<Vec3> CheckVec3(const nlohmann::json& value, const std::string& path,
                              const std::string& expected, ErrorReport& report);

std::optional<Mat3> CheckMatrix3(const nlohmann::json& value, const std::string& path,
                                 ErrorReport& report);

}  // namespace cosserat::io::detail

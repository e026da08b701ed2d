#pragma once
/// \file
/// JSON text -> document, with the input errors that nlohmann::json::parse would either throw on
/// or silently accept reported as message lines: malformed JSON (with line and column), duplicate
/// keys (parse would keep the last), and numbers that overflow a double (parse would give up).

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace cosserat::io::detail {

struct JsonDocument {
  std::optional<nlohmann::json> value;  ///< empty when the text is not JSON
  std::vector<std::string> errors;      ///< message lines, in document order
};

/// Parses `text`. Malformed JSON gives no value and one line
/// `<source_name>: invalid JSON at line L, column C: ...`. A duplicate key gives the line
/// `<path>: expected each key once in an object, got a duplicate key`, and the document keeps the
/// last value. A number overflowing a double becomes ±infinity in the document, so that the typed
/// reads of json_reader.hpp report it where it is used; past 64 such numbers the text is reported
/// as invalid JSON (each one costs a re-parse).
JsonDocument ParseJsonDocument(const std::string& text, const std::string& source_name);

}  // namespace cosserat::io::detail

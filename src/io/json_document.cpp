#include "cosserat/io/json_document.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <map>
#include <utility>

#include "cosserat/io/json_path.hpp"

namespace cosserat::io::detail {
namespace {

using json = nlohmann::json;

/// Overflowing numbers recovered from (each costs a re-parse); beyond this the parse stops.
constexpr std::size_t kMaxOverflowRetries = 64;

/// A SAX handler that builds the document while tracking the JSON path, so that duplicate keys
/// and the number that overflowed can be reported where they are.
class DocumentBuilder final : public json::json_sax_t {
 public:
  /// Nesting this deep is no problem or study file (they nest a few levels).
  static constexpr std::size_t kMaxDepth = 128;
  static constexpr int kDepthFailure = -1;  ///< Failure::id of a file nested too deep
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
    if (top.container->contains(key)) duplicate_keys_.push_back(ChildPath(top.path, key));
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
    if (stack_.size() >= kMaxDepth) {  // each level keeps its path: deep files cost depth²
      failure_ = Failure{kDepthFailure, 0, "", "", "arrays and objects nested deeper than " +
                                                       std::to_string(kMaxDepth) + " levels"};
      return false;
    }
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

/// `text` with every byte that is not part of well-formed UTF-8 written as \xNN: the parser
/// quotes the bytes it stopped at, and a message must stay printable (Python raises an empty
/// ValueError for a message that is not UTF-8).
std::string EscapeInvalidUtf8(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    const std::size_t length = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3
                                          : (c >> 3) == 0x1E ? 4 : 0;
    bool whole = length > 0 && i + length <= text.size();
    for (std::size_t k = 1; whole && k < length; ++k)
      whole = (static_cast<unsigned char>(text[i + k]) >> 6) == 0x2;
    if (whole) {
      out.append(text, i, length);
      i += length;
    } else {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02X", c);
      out += hex;
      ++i;
    }
  }
  return out;
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
    if (text[i] == '\n')
      ++line, column = 1;
    else
      ++column;
  }
  const std::size_t bracket = failure.message.find("] ");
  const std::string what =
      bracket == std::string::npos ? failure.message : failure.message.substr(bracket + 2);
  return "at line " + std::to_string(line) + ", column " + std::to_string(column) + ": " + what;
}

/// "; JSON has no comments ..." when the parse stopped at a "//" or "/*" (the text from the
/// failure's position back to the line's start holds one), else empty.
std::string CommentHint(const std::string& text, std::size_t position) {
  const std::size_t end = std::min(position + 1, text.size());
  const std::size_t newline = text.rfind('\n', end == 0 ? 0 : end - 1);
  const std::size_t begin = newline == std::string::npos ? 0 : newline + 1;
  const std::string line = text.substr(begin, end - begin);
  if (line.find("//") == std::string::npos && line.find("/*") == std::string::npos) return "";
  return "; JSON has no comments: put notes in a \"description\" string (the top level and "
         "robot take one)";
}

}  // namespace

JsonDocument ParseJsonDocument(const std::string& text, const std::string& source_name) {
  std::string work = text;
  std::map<std::string, double> overflowed;
  // Each pass either succeeds, fails for good, or blanks one overflowing number and retries.
  for (;;) {
    DocumentBuilder builder(&overflowed);
    if (json::sax_parse(work, &builder)) {
      JsonDocument doc{builder.TakeDocument(), {}};
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
    if (failure.id == DocumentBuilder::kDepthFailure)
      return {std::nullopt, {source_name + ": invalid JSON: " + failure.message}};
    return {std::nullopt,
            {source_name + ": invalid JSON " + EscapeInvalidUtf8(SyntaxErrorText(failure, text)) +
             CommentHint(text, failure.position)}};
  }
}

}  // namespace cosserat::io::detail

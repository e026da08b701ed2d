#include "cosserat/io/json_path.hpp"

#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>

namespace cosserat::io::detail {
namespace {

bool IsPlainKey(const std::string& key) {
  return !key.empty() && std::all_of(key.begin(), key.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '_' || c == '-';
  });
}

}  // namespace

std::string ChildPath(const std::string& parent, const std::string& key) {
  if (!IsPlainKey(key)) return parent + "[" + nlohmann::json(key).dump() + "]";
  return parent.empty() ? key : parent + "." + key;
}

std::string ElementPath(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

std::string ShownPath(const std::string& path) { return path.empty() ? "(top level)" : path; }

}  // namespace cosserat::io::detail

#pragma once
/// \file
/// A named choice of a problem file read straight into its enum (problem_kinds.hpp).

#include <optional>
#include <string>
#include <vector>

#include "cosserat/io/json_reader.hpp"
#include "cosserat/io/problem_kinds.hpp"

namespace cosserat::io::detail {

/// ReadChoice among `choices` (by default every name of Enum), as the enum value.
template <typename Enum>
std::optional<Enum> ReadEnum(const ObjectReader& o, const std::string& key, Presence presence,
                             const std::vector<std::string>& choices = Names<Enum>()) {
  const std::optional<std::string> name = ReadChoice(o, key, choices, presence);
  Enum value{};
  if (!name || !FromString(*name, &value)) return std::nullopt;
  return value;
}

}  // namespace cosserat::io::detail

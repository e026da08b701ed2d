#pragma once
/// \file
/// JSON paths as error messages show them: `rod.section.radius`, `rod.stiffness_profile[2]`,
/// `rod["a b"]`. Shared by every input-file parser so that all of them name places alike.

#include <cstddef>
#include <string>

namespace cosserat::io::detail {

/// `rod` + `length` -> `rod.length`; a key that is not a plain identifier (letters, digits, `_`,
/// `-`) is quoted: `rod["a b"]`. An empty parent is the top level.
std::string ChildPath(const std::string& parent, const std::string& key);

/// `rod.stiffness_profile` + 2 -> `rod.stiffness_profile[2]`.
std::string ElementPath(const std::string& parent, std::size_t index);

/// The path as printed at the start of an error line: the top level is "(top level)".
std::string ShownPath(const std::string& path);

}  // namespace cosserat::io::detail

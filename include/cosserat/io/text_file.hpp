#pragma once
/// \file
/// Reading an input file whole, with the refusals every reader shares: a directory, an
/// unreadable path, and a file larger than any problem or study (a device such as /dev/zero
/// would otherwise be read until memory runs out).

#include <cstddef>
#include <string>

namespace cosserat::io {

/// The most an input file may hold, bytes (256 MiB: tables of a million rows fit).
constexpr std::size_t kMaxInputBytes = std::size_t{256} << 20;

/// Reads the file at `path` into *text. False, with the reason in *why ("it is a directory",
/// the system's message, "larger than 256 MiB"), when it cannot.
bool ReadTextFile(const std::string& path, std::string* text, std::string* why);

}  // namespace cosserat::io

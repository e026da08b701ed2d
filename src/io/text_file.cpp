#include "cosserat/io/text_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace cosserat::io {

bool ReadTextFile(const std::string& path, std::string* text, std::string* why) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    *why = "it is a directory";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *why = std::strerror(errno);
    return false;
  }
  text->clear();
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    text->append(chunk, static_cast<std::size_t>(in.gcount()));
    if (text->size() > kMaxInputBytes) {
      *why = "larger than " + std::to_string(kMaxInputBytes >> 20) + " MiB";
      return false;
    }
  }
  if (in.bad()) {
    *why = "read error";
    return false;
  }
  return true;
}

}  // namespace cosserat::io

#include "output_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace cosserat::apps {
namespace {

std::runtime_error CannotWrite(const std::string& path) {
  return std::runtime_error("cannot write '" + path + "' (" + std::strerror(errno) + ")");
}

}  // namespace

OutputFile::OutputFile(const std::string& path) : target_(path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  // Through a symbolic link to the file it names, so the link stays a link.
  const fs::path resolved = fs::weakly_canonical(path, ec);
  if (!ec) target_ = resolved.string();
  const fs::file_status status = fs::status(target_, ec);
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    if (fs::is_directory(status)) {
      errno = EISDIR;
      throw CannotWrite(path);
    }
    stream_.open(target_);  // a device or a pipe: nothing to replace
    if (!stream_) throw CannotWrite(path);
    return;
  }
  temporary_ = target_ + ".partial-" + std::to_string(::getpid());
  stream_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!stream_) throw CannotWrite(path);
}

OutputFile::~OutputFile() {
  if (committed_ || temporary_.empty()) return;
  stream_.close();
  std::remove(temporary_.c_str());
}

void OutputFile::Commit() {
  stream_.flush();
  const bool written = static_cast<bool>(stream_);
  stream_.close();
  if (!written) throw std::runtime_error("writing '" + target_ + "' failed");
  if (!temporary_.empty() && std::rename(temporary_.c_str(), target_.c_str()) != 0)
    throw CannotWrite(target_);
  committed_ = true;
}

}  // namespace cosserat::apps

#include "output_file.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <stdexcept>

namespace cosserat::apps {
namespace {

namespace fs = std::filesystem;

/// The reason in words: a missing directory is named (the tool does not make directories for a
/// file it writes), any other failure is the system's.
std::runtime_error CannotWrite(const std::string& path) {
  const int error = errno;  // before the calls below, which may set it
  const std::string reason = std::strerror(error);
  const fs::path directory = fs::path(path).parent_path();
  std::error_code ec;
  if (error == ENOENT && !directory.empty() && !fs::exists(directory, ec))
    return std::runtime_error("cannot write '" + path + "' (no directory '" +
                              directory.string() + "')");
  return std::runtime_error("cannot write '" + path + "' (" + reason + ")");
}

/// The file a chain of symbolic links ends at, followed link by link (a link to a file not
/// written yet stays a link: the file is made where it points).
fs::path FollowLinks(fs::path p) {
  std::error_code ec;
  for (int hops = 0; hops < 40 && fs::is_symlink(fs::symlink_status(p, ec)); ++hops) {
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) break;
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  return p;
}

/// The standard stream (1 or 2) that `path` is, through any links (`/dev/stdout`, or a file a
/// shell redirected the output to); 0 when neither.
int StandardStreamAt(const std::string& path) {
  struct stat target {}, stream {};
  if (::stat(path.c_str(), &target) != 0) return 0;
  for (int fd : {STDOUT_FILENO, STDERR_FILENO})
    if (::fstat(fd, &stream) == 0 && stream.st_dev == target.st_dev &&
        stream.st_ino == target.st_ino)
      return fd;
  return 0;
}

}  // namespace

OutputFile::OutputFile(const std::string& path) : target_(path) {
  // The process's own output (a pipe, a terminal, a file the shell opened): written through the
  // stream already open on it, which keeps its place among the other writes.
  if (const int fd = StandardStreamAt(path)) {
    out_ = fd == STDOUT_FILENO ? &std::cout : &std::cerr;
    return;
  }
  target_ = FollowLinks(path).string();
  std::error_code ec;
  const fs::file_status status = fs::status(target_, ec);
  if (fs::is_directory(status)) {
    errno = EISDIR;
    throw CannotWrite(path);
  }
  // Written in place, as before: a device or a pipe (nothing to replace), the process's own
  // output, a file with other hard links (a new file would leave them behind).
  bool in_place = fs::exists(status) && !fs::is_regular_file(status);
  if (fs::is_regular_file(status)) in_place = fs::hard_link_count(target_, ec) > 1;
  if (!in_place) {
    temporary_ = target_ + ".partial-" + std::to_string(::getpid());
    stream_.open(temporary_, std::ios::binary | std::ios::trunc);
    if (stream_ && fs::is_regular_file(status))  // the target's permissions carry over
      fs::permissions(temporary_, status.permissions(), ec);
    // A directory that takes no new file, with a target that can be written: in place.
    if (!stream_) temporary_.clear();
  }
  if (temporary_.empty()) {
    stream_.open(target_, std::ios::binary | std::ios::trunc);
    if (!stream_) throw CannotWrite(path);
  }
}

OutputFile::~OutputFile() {
  if (committed_ || temporary_.empty()) return;
  stream_.close();
  std::remove(temporary_.c_str());
}

void OutputFile::Commit() {
  if (out_ != &stream_) {
    out_->flush();
    if (!*out_) throw std::runtime_error("writing '" + target_ + "' failed");
    committed_ = true;
    return;
  }
  stream_.flush();
  const bool written = static_cast<bool>(stream_);
  stream_.close();
  if (!written) throw std::runtime_error("writing '" + target_ + "' failed");
  if (!temporary_.empty() && std::rename(temporary_.c_str(), target_.c_str()) != 0)
    throw CannotWrite(target_);
  committed_ = true;
}

}  // namespace cosserat::apps

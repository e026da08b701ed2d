#pragma once
// An output file of `cosserat solve` (--out, --csv) written whole or not at all: the text goes
// to a temporary file beside the target (with its permissions), which replaces the target only
// on Commit(). A run that is refused, fails or is killed leaves the last result in place (a
// truncated target would lose it). Symbolic links are followed to the file they name. Written
// in place instead: what is not a regular file (a pipe, a device), a file with other hard
// links, and a target whose directory takes no new file. The process's own stdout or stderr
// (`--out /dev/stdout`, into a pipe or a file the shell opened) is written through std::cout or
// std::cerr, which keep its place among the other writes.

#include <fstream>
#include <ostream>
#include <string>

namespace cosserat::apps {

class OutputFile {
 public:
  /// Opens the temporary file; throws std::runtime_error naming `path` when it cannot be
  /// written (a bad path fails before the run).
  explicit OutputFile(const std::string& path);
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  /// Removes the temporary file unless committed.
  ~OutputFile();

  std::ostream& stream() { return *out_; }
  /// Flushes and moves the text onto the target; throws std::runtime_error if that fails.
  void Commit();

 private:
  std::string target_;     ///< the file the user named (symbolic links followed)
  std::string temporary_;  ///< empty when writing the target directly
  std::ofstream stream_;
  std::ostream* out_ = &stream_;  ///< stream_, or std::cout / std::cerr when that is the target
  bool committed_ = false;
};

}  // namespace cosserat::apps

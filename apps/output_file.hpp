#pragma once
// An output file of `cosserat solve` (--out, --csv) written whole or not at all: the text goes
// to a temporary file beside the target, which replaces the target only on Commit(). A run that
// is refused, fails or is killed leaves the last result in place (a truncated target would
// lose it). Targets that are not regular files (/dev/stdout, a pipe) are written directly.

#include <fstream>
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

  std::ofstream& stream() { return stream_; }
  /// Flushes and moves the text onto the target; throws std::runtime_error if that fails.
  void Commit();

 private:
  std::string target_;     ///< the file the user named (symbolic links followed)
  std::string temporary_;  ///< empty when writing the target directly
  std::ofstream stream_;
  bool committed_ = false;
};

}  // namespace cosserat::apps

// AtomicFile.h -- output files appear whole or not at all: writers write to a temporary name beside the
// target and rename it when complete; an abandoned temporary is removed.
#pragma once
#include <string>

namespace rv {

class AtomicFile {
public:
  /// Checks that `path` can be written (InputError naming `what`, e.g. "-o", when not).
  AtomicFile(std::string path, const std::string& what);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  /// Where to write now.
  const std::string& tempPath() const { return temp_; }
  const std::string& path() const { return path_; }
  /// Renames the temporary to the target; throws ComputationError on failure.
  void commit();

private:
  std::string path_, temp_;
  bool committed_ = false;
};

/// Throws InputError naming `what` when `path` is empty, a directory, or in a folder that cannot be written.
void checkWritable(const std::string& path, const std::string& what);

} // namespace rv

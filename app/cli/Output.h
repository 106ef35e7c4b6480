// Output.h -- a command's output: a file written under a temporary name and renamed when complete, or
// standard output.
#pragma once
#include "dynamics/core/Errors.h"
#include "dynamics/io/AtomicFile.h"

#include <cstdio>
#include <memory>
#include <string>

namespace rv {

/// Where a command writes its table: `path`, or standard output when it is empty.
class Output {
public:
  explicit Output(const std::string& path) {
    if (path.empty()) return;
    file_ = std::make_unique<AtomicFile>(path, "-o");
    out_ = std::fopen(file_->tempPath().c_str(), "w");
    if (!out_) throw InputError("-o " + path + ": cannot open for writing");
  }
  ~Output() {
    if (file_ && out_) std::fclose(out_);
  }
  FILE* get() const { return out_; }
  /// Flushes and renames the file into place.
  void commit() {
    if (!file_) {
      std::fflush(out_);
      return;
    }
    const bool ok = std::fflush(out_) == 0 && !std::ferror(out_);
    std::fclose(out_);
    out_ = nullptr;
    if (!ok) throw ComputationError("cannot write " + file_->path());
    file_->commit();
  }

private:
  std::unique_ptr<AtomicFile> file_;
  FILE* out_ = stdout;
};

} // namespace rv

#include "dynamics/io/AtomicFile.h"

#include "dynamics/core/Errors.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <unistd.h>

namespace rv {

namespace fs = std::filesystem;

void checkWritable(const std::string& path, const std::string& what) {
  if (path.empty()) throw InputError(what + ": empty output path");
  const fs::path p(path);
  std::error_code ec;
  if (fs::is_directory(p, ec)) throw InputError(what + " " + path + ": is a directory");
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec)) throw InputError(what + " " + path + ": no such folder " + dir.string());
  if (::access(dir.c_str(), W_OK) != 0)
    throw InputError(what + " " + path + ": cannot write in " + dir.string() + " (" + std::strerror(errno) +
                     ")");
  if (fs::exists(p, ec) && ::access(p.c_str(), W_OK) != 0)
    throw InputError(what + " " + path + ": cannot overwrite (" + std::strerror(errno) + ")");
}

AtomicFile::AtomicFile(std::string path, const std::string& what) : path_(std::move(path)) {
  checkWritable(path_, what);
  const fs::path p(path_);
  // keep the extension: some writers choose the format by it
  temp_ = (p.parent_path() /
           ("." + p.stem().string() + ".partial-" + std::to_string(::getpid()) + p.extension().string()))
              .string();
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    std::error_code ec;
    fs::remove(temp_, ec);
  }
}

void AtomicFile::commit() {
  std::error_code ec;
  fs::rename(temp_, path_, ec);
  if (ec) throw ComputationError("cannot rename " + temp_ + " to " + path_ + ": " + ec.message());
  committed_ = true;
}

} // namespace rv

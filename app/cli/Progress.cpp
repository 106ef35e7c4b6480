#include "app/cli/Progress.h"

#include <atomic>
#include <csignal>
#include <cstdio>
#include <unistd.h>

namespace rv {

namespace {
std::atomic<bool> g_interrupted{false};
extern "C" void onSigint(int) {
  g_interrupted.store(true);
}
} // namespace

void installInterruptHandler() {
  struct sigaction sa {};
  sa.sa_handler = onSigint;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
}

bool interrupted() {
  return g_interrupted.load();
}

bool stdoutIsTerminal() {
  return ::isatty(STDOUT_FILENO) == 1;
}

Progress::Progress(std::string label, bool show)
    : label_(std::move(label)), tty_(show && ::isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() {
  clear();
}

void Progress::update(double fraction) {
  update(fraction, {});
}

void Progress::update(double fraction, const std::string& detail) {
  if (!tty_) return;
  const int pct = static_cast<int>(fraction * 100);
  const auto now = std::chrono::steady_clock::now();
  const std::lock_guard lock(mutex_); // a sweep's threads report at once
  if (shown_ && ((pct == last_ && detail.empty()) || now - at_ < std::chrono::milliseconds(200))) return;
  last_ = pct, at_ = now, shown_ = true;
  std::fprintf(stderr, "\r\033[K%s: %3d%%%s%s", label_.c_str(), pct, detail.empty() ? "" : "  ",
               detail.c_str());
  std::fflush(stderr);
}

void Progress::clear() {
  const std::lock_guard lock(mutex_);
  if (!shown_) return;
  shown_ = false;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
}

ToolControl interruptibleControl(Progress& progress) {
  ToolControl c;
  c.stopRequested = [] { return interrupted(); };
  c.progress = [&progress](double f) { progress.update(f); };
  return c;
}

} // namespace rv

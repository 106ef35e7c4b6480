#include "dynamics/jobs/JobTree.h"

#include <algorithm>
#include <utility>

namespace rv {

JobTree::~JobTree() {
  removeAll();
}

Job& JobTree::add(std::unique_ptr<Task> task, Job* parent, int number) {
  const bool free = number > 0 && !find(number) && !windowIds_.contains(number);
  const int id = free ? number : nextId_;
  nextId_ = std::max(nextId_, id + 1);
  if (task->ownsItsScene()) windowIds_.insert(id);
  // by number, after its parent (a new job's number is the largest: it goes last)
  auto at = std::find_if(jobs_.begin(), jobs_.end(), [id](const auto& j) { return j->id() > id; });
  if (parent) {
    const auto p =
        std::find_if(jobs_.begin(), jobs_.end(), [parent](const auto& j) { return j.get() == parent; });
    if (p != jobs_.end() && at <= p) at = p + 1;
  }
  at = jobs_.insert(at, std::make_unique<Job>(id, std::move(task), parent));
  (*at)->pauseAt(std::exchange(pauseNext_, std::numeric_limits<double>::infinity()));
  return **at;
}

std::vector<Job*> JobTree::children(const Job& job) const {
  std::vector<Job*> out;
  for (const auto& j : jobs_)
    if (j->parent() == &job) out.push_back(j.get());
  return out;
}

void JobTree::remove(Job& job) {
  for (Job* child : children(job))
    remove(*child);
  job.stop();
  std::erase_if(jobs_, [&](const std::unique_ptr<Job>& j) { return j.get() == &job; });
}

std::vector<Job*> JobTree::subtree(Job& job) const {
  std::vector<Job*> out{&job};
  for (std::size_t i = 0; i < out.size(); ++i)
    for (Job* c : children(*out[i]))
      out.push_back(c);
  return out;
}

void JobTree::stopAll() {
  for (auto& j : jobs_)
    j->stop();
}

void JobTree::removeAll() {
  stopAll();
  jobs_.clear();
}

std::vector<Job*> JobTree::jobs() const {
  std::vector<Job*> out;
  for (const auto& j : jobs_)
    out.push_back(j.get());
  return out;
}

Job* JobTree::find(int id) const {
  for (const auto& j : jobs_)
    if (j->id() == id) return j.get();
  return nullptr;
}

} // namespace rv

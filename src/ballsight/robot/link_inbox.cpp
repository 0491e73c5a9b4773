#include "ballsight/robot/link_inbox.hpp"

namespace ballsight {

bool LinkInbox::deliver(LinkUpdate update) {
  {
    const std::lock_guard lock(mutex_);
    if (update.service_id == service_id_ && update.seq <= last_seq_) return false;
    if (update.service_id == service_id_) status_.gaps += update.seq - last_seq_ - 1;
    service_id_ = update.service_id;
    last_seq_ = update.seq;
    ++status_.delivered;
    ready_.push_back(std::move(update));
    if (ready_.size() > keep_) ready_.pop_front();
  }
  changed_.notify_all();
  return true;
}

std::optional<LinkUpdate> LinkInbox::take(std::chrono::milliseconds timeout, bool newest) {
  std::unique_lock lock(mutex_);
  changed_.wait_for(lock, timeout, [&] { return !ready_.empty() || closed_; });
  if (ready_.empty()) return std::nullopt;
  LinkUpdate u = std::move(newest ? ready_.back() : ready_.front());
  if (newest) {
    ready_.clear();
  } else {
    ready_.pop_front();
  }
  return u;
}

void LinkInbox::close() {
  {
    const std::lock_guard lock(mutex_);
    closed_ = true;
  }
  changed_.notify_all();
}

std::uint64_t LinkInbox::last_seq() const {
  const std::lock_guard lock(mutex_);
  return last_seq_;
}

std::string LinkInbox::service_id() const {
  const std::lock_guard lock(mutex_);
  return service_id_;
}

LinkStatus LinkInbox::status() const {
  const std::lock_guard lock(mutex_);
  return status_;
}

void LinkInbox::update_status(const std::function<void(LinkStatus&)>& change) {
  const std::lock_guard lock(mutex_);
  change(status_);
}

}  // namespace ballsight

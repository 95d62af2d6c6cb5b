// NetIndexCache (see the header) and NetIndex::load_shared.
#include "net/net_index_cache.hpp"

#include <algorithm>
#include <system_error>

namespace signalsim::sumo {

NetIndexCache::NetIndexCache(std::size_t capacity) : capacity_(std::max<std::size_t>(capacity, 1)) {}

std::optional<NetIndexCache::Stamp> NetIndexCache::stamp_of(const std::string& path) {
  std::error_code size_error, time_error;
  const std::uintmax_t size = std::filesystem::file_size(path, size_error);
  const auto modified = std::filesystem::last_write_time(path, time_error);
  if (size_error || time_error) return std::nullopt;
  return Stamp{size, modified};
}

std::shared_ptr<const NetIndex> NetIndexCache::get(const std::string& path) {
  const std::optional<Stamp> before = stamp_of(path);
  {
    std::lock_guard lock(mutex_);
    const auto hit = std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.path == path; });
    if (hit != entries_.end()) {
      if (before && hit->stamp == *before) {
        entries_.splice(entries_.begin(), entries_, hit);  // most recently used
        return hit->net;
      }
      entries_.erase(hit);  // changed (or gone): read again
    }
  }
  // Loaded outside the lock: another net may be looked up meanwhile. A missing or unreadable file
  // throws here, as NetIndex::load does.
  auto net = std::make_shared<const NetIndex>(NetIndex::load(path));
  // A file written while it was read is not kept: the next run reads it again.
  if (!before || stamp_of(path) != before) return net;
  std::lock_guard lock(mutex_);
  entries_.remove_if([&](const Entry& e) { return e.path == path; });  // loaded by two threads at once
  entries_.push_front({path, *before, net});
  while (entries_.size() > capacity_) entries_.pop_back();
  return net;
}

std::size_t NetIndexCache::size() const {
  std::lock_guard lock(mutex_);
  return entries_.size();
}

void NetIndexCache::clear() {
  std::lock_guard lock(mutex_);
  entries_.clear();
}

NetIndexCache& NetIndexCache::process() {
  static NetIndexCache cache;
  return cache;
}

std::shared_ptr<const NetIndex> NetIndex::load_shared(const std::string& path) {
  return NetIndexCache::process().get(path);
}

}  // namespace signalsim::sumo

// NetIndexCache: the nets a process has loaded, shared by the runs that use them, so that a process
// running many scenarios on one net (a batch worker) reads the net once. Keyed by the path as given
// (messages name it), the file's size and its modification time: a changed file is read again.
// The answers of a shared index are those of a fresh one (net_index.hpp: reading on demand gives
// the answers of a whole reading, whatever was looked up before).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <list>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "net/net_index.hpp"

namespace signalsim::sumo {

class NetIndexCache {
 public:
  /// Keeps at most `capacity` nets (at least one), dropping the least recently used. An index
  /// reading on demand holds its parsed file, about three times the inflated text (Bad Hersfeld's
  /// 23 MB: about 70 MiB); an index still in use by a run stays alive until the run drops it.
  explicit NetIndexCache(std::size_t capacity = 4);

  /// The index of `path` (NetReading::OnDemand): the cached one when the file has the size and
  /// modification time it had when loaded, else loaded now. Throws NetError as NetIndex::load
  /// (nothing is cached then). Safe to call from several threads.
  std::shared_ptr<const NetIndex> get(const std::string& path);

  /// Nets cached now.
  std::size_t size() const;
  void clear();

  /// The process's cache (used by NetIndex::load_shared).
  static NetIndexCache& process();

 private:
  struct Stamp {
    std::uintmax_t size = 0;
    std::filesystem::file_time_type modified{};
    bool operator==(const Stamp&) const = default;
  };
  static std::optional<Stamp> stamp_of(const std::string& path);

  struct Entry {
    std::string path;
    Stamp stamp;
    std::shared_ptr<const NetIndex> net;
  };
  std::size_t capacity_;
  mutable std::mutex mutex_;
  std::list<Entry> entries_;  // most recently used first
};

}  // namespace signalsim::sumo

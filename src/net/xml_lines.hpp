// Line numbers of XML elements for messages: pugixml reports byte offsets, a user wants "file:line".
// Private to src/net.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace signalsim::sumo {

/// The newlines of a text, so that the line of a byte offset is one binary search.
class LineIndex {
 public:
  explicit LineIndex(const std::string& text) {
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') newlines_.push_back(i);
  }
  /// 1-based line of byte `offset` (pugixml's offset_debug(); < 0 gives 0, "unknown").
  int line_of(std::ptrdiff_t offset) const {
    if (offset < 0) return 0;
    const auto it = std::lower_bound(newlines_.begin(), newlines_.end(), static_cast<std::size_t>(offset));
    return static_cast<int>(it - newlines_.begin()) + 1;
  }

 private:
  std::vector<std::size_t> newlines_;
};

}  // namespace signalsim::sumo

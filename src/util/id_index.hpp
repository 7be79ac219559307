// Id -> position in a list of ids (node, part, curve ids as the deck numbers them), the first
// position when an id repeats. A table over [smallest id, largest id] when the ids fill at
// least about half of that range, as meshers number them: a lookup is one load, and building
// it no allocation per id (a hash map was a tenth of reading a large deck, rebuilt at each
// Model::finalize). A hash map for scattered ids.
#pragma once

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace crumple::util {

class IdIndex {
 public:
  static constexpr int32_t kAbsent = -1;

  template <class Ids>
  void assign(const Ids& ids) {
    clear();
    if (ids.empty()) return;
    const auto [lo, hi] = std::minmax_element(ids.begin(), ids.end());
    // The span as unsigned: ids of any sign and size cannot overflow it.
    const uint64_t span = static_cast<uint64_t>(*hi) - static_cast<uint64_t>(*lo);
    if (span < 2 * static_cast<uint64_t>(ids.size()) + 64) {
      min_ = *lo;
      dense_.assign(span + 1, kAbsent);
      for (std::size_t i = 0; i < ids.size(); ++i) {
        int32_t& slot = dense_[static_cast<std::size_t>(ids[i] - min_)];
        if (slot == kAbsent) slot = static_cast<int32_t>(i);
      }
      return;
    }
    sparse_.reserve(ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i) sparse_.emplace(ids[i], static_cast<int32_t>(i));
  }

  // The position of `id`, or kAbsent.
  int32_t find(int64_t id) const {
    if (!dense_.empty()) {
      const uint64_t k = static_cast<uint64_t>(id) - static_cast<uint64_t>(min_);
      return k < dense_.size() ? dense_[k] : kAbsent;
    }
    const auto it = sparse_.find(id);
    return it == sparse_.end() ? kAbsent : it->second;
  }

  // Frees the memory as well.
  void clear() {
    std::vector<int32_t>().swap(dense_);
    std::unordered_map<int64_t, int32_t>().swap(sparse_);
    min_ = 0;
  }

 private:
  int64_t min_ = 0;
  std::vector<int32_t> dense_;
  std::unordered_map<int64_t, int32_t> sparse_;
};

}  // namespace crumple::util

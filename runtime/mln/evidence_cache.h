// A least-recently-used cache of Markov logic results keyed by the evidence: the key is the
// exact evidence a kit extracted (a bit vector, or any vector of integers that encodes it; no
// hash collision is trusted: equal hashes are compared element by element). Kits keep one per
// chain and re-run inference only on a miss.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <list>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

namespace ksmc::runtime::mln {

template <class Result, class Element = std::uint8_t>
class EvidenceCache {
 public:
  using Key = std::vector<Element>;
  using Value = std::shared_ptr<const Result>;

  explicit EvidenceCache(std::size_t capacity) : capacity_(capacity == 0 ? 1 : capacity) {}

  // The cached result for `key` (now the most recent), or nullptr.
  Value find(const Key& key) {
    auto [lo, hi] = index_.equal_range(hash(key));
    for (auto it = lo; it != hi; ++it)
      if (it->second->key == key) {
        lru_.splice(lru_.begin(), lru_, it->second);  // iterators stay valid
        return lru_.front().value;
      }
    return nullptr;
  }

  // Adds `value` for `key` (not already present) and evicts the least recent entry when full.
  void insert(Key key, Value value) {
    const std::uint64_t h = hash(key);
    lru_.push_front(Entry{h, std::move(key), std::move(value)});
    index_.emplace(h, lru_.begin());
    if (lru_.size() <= capacity_) return;
    const auto last = std::prev(lru_.end());
    auto [lo, hi] = index_.equal_range(last->hash);
    for (auto it = lo; it != hi; ++it)
      if (it->second == last) {
        index_.erase(it);
        break;
      }
    lru_.erase(last);
  }

  std::size_t size() const noexcept { return lru_.size(); }
  std::size_t capacity() const noexcept { return capacity_; }

  // FNV-1a over the elements.
  static std::uint64_t hash(const Key& key) {
    std::uint64_t h = 1469598103934665603ULL;
    for (const Element e : key) {
      h ^= static_cast<std::uint64_t>(e);
      h *= 1099511628211ULL;
    }
    return h;
  }

 private:
  struct Entry {
    std::uint64_t hash;
    Key key;
    Value value;
  };
  std::size_t capacity_;
  std::list<Entry> lru_;  // most recent first
  std::unordered_multimap<std::uint64_t, typename std::list<Entry>::iterator> index_;
};

}  // namespace ksmc::runtime::mln

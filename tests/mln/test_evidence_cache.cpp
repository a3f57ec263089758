// EvidenceCache: hits by exact key, least-recently-used eviction, integer keys.
#include <catch2/catch.hpp>

#include "runtime/mln/evidence_cache.h"

using ksmc::runtime::mln::EvidenceCache;

TEST_CASE("evidence cache: exact-key hits and LRU eviction", "[mln][cache]") {
  EvidenceCache<int> cache(2);
  const std::vector<std::uint8_t> a{1, 0, 1}, b{0, 1, 1}, c{1, 1, 1};
  CHECK(cache.find(a) == nullptr);
  cache.insert(a, std::make_shared<const int>(10));
  cache.insert(b, std::make_shared<const int>(20));
  REQUIRE(cache.find(a) != nullptr);  // a is now the most recent
  CHECK(*cache.find(a) == 10);
  cache.insert(c, std::make_shared<const int>(30));  // evicts b, the least recent
  CHECK(cache.size() == 2);
  CHECK(cache.find(b) == nullptr);
  CHECK(*cache.find(a) == 10);
  CHECK(*cache.find(c) == 30);
  CHECK(cache.find(std::vector<std::uint8_t>{1, 0}) == nullptr);  // a prefix is another key
}

TEST_CASE("evidence cache: capacity 0 keeps one entry; integer keys", "[mln][cache]") {
  EvidenceCache<int, std::int32_t> cache(0);
  CHECK(cache.capacity() == 1);
  cache.insert({3, 1, 2}, std::make_shared<const int>(1));
  cache.insert({3, 2, 1}, std::make_shared<const int>(2));
  CHECK(cache.size() == 1);
  CHECK(cache.find({3, 1, 2}) == nullptr);
  CHECK(*cache.find({3, 2, 1}) == 2);
  CHECK(EvidenceCache<int, std::int32_t>::hash({1, 2}) != EvidenceCache<int, std::int32_t>::hash({2, 1}));
}

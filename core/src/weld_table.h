#pragma once
// Private to core: exact-coordinate vertex welding in expected O(1) per point (open addressing),
// shared by load_mesh and build_mesh_edges.
#include <Eigen/Core>
#include <cstdint>
#include <cstring>
#include <vector>

#include "huge_pages.h"
#include "prefetch.h"

namespace cordgrasp::detail {

/// How many points ahead a weld prefetches its table slot (WeldTable::prefetch): far enough
/// for the fetch to arrive, near enough to stay in cache.
inline constexpr int kWeldLookAhead = 8;

/// Set of point ids keyed by their exact coordinates (−0.0 equals +0.0, as `==` says). The table
/// holds ids only; `point_of(id)` gives an id's point. Ids are the caller's (any int ≥ 0).
class WeldTable {
 public:
  /// Room for about `expected` distinct points before the first rehash.
  explicit WeldTable(std::size_t expected = 0) {
    std::size_t size = 16;
    while (size < 2 * expected) size *= 2;
    assign_huge(slots_, size, kEmpty);
  }

  /// Asks the processor to fetch p's first slot: a look-up a few points later then finds it in
  /// cache (the table is larger than the cache for a mesh of millions of vertices).
  void prefetch(const Eigen::Vector3d& p) const {
    detail::prefetch(slots_.data() + (hash(p) & (slots_.size() - 1)));
  }

  /// The id of a stored point equal to p, or −1 after storing `new_id` for p.
  template <typename PointOf>
  int find_or_insert(const Eigen::Vector3d& p, int new_id, PointOf&& point_of) {
    if (2 * (count_ + 1) > slots_.size()) grow(point_of);
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = hash(p) & mask;; i = (i + 1) & mask) {
      const int id = slots_[i];
      if (id == kEmpty) {
        slots_[i] = new_id;
        ++count_;
        return -1;
      }
      if (point_of(id) == p) return id;
    }
  }

 private:
  static constexpr int kEmpty = -1;

  static std::uint64_t bits(double x) {
    if (x == 0.0) x = 0.0;  // −0.0 and +0.0 weld
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
  }
  static std::size_t hash(const Eigen::Vector3d& p) {
    std::uint64_t h = bits(p.x()) * 0x9E3779B97F4A7C15ull;
    h = (h ^ (h >> 29) ^ bits(p.y())) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 31) ^ bits(p.z())) * 0x94D049BB133111EBull;
    return std::size_t(h ^ (h >> 32));
  }
  template <typename PointOf>
  void grow(PointOf&& point_of) {
    std::vector<int> old;
    assign_huge(old, slots_.size() * 2, kEmpty);
    old.swap(slots_);
    const std::size_t mask = slots_.size() - 1;
    for (int id : old) {
      if (id == kEmpty) continue;
      std::size_t i = hash(point_of(id)) & mask;
      while (slots_[i] != kEmpty) i = (i + 1) & mask;
      slots_[i] = id;
    }
  }

  std::vector<int> slots_;
  std::size_t count_ = 0;
};

}  // namespace cordgrasp::detail

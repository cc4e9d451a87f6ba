#pragma once
// Private to core: transparent huge pages for the few arrays that grow with a mesh's triangle
// count. A scan of millions of triangles allocates hundreds of MB in arrays that are written
// once and then walked: with 4 KiB pages the first touches (page faults) and TLB misses cost
// about a fifth of planning it. Linux backs a range marked MADV_HUGEPAGE with 2 MiB pages when
// its transparent-huge-page mode is `madvise` or `always` (a no-op elsewhere).
#include <cstddef>
#include <vector>

namespace cordgrasp::detail {

/// Marks the whole 2 MiB pages inside [p, p + bytes) for transparent huge pages; does nothing
/// for ranges under a few MiB or where the system has no such pages.
void advise_huge_pages(const void* p, std::size_t bytes);

/// v.reserve(n), with the reserved storage advised for huge pages before it is first touched.
template <typename T, typename A>
void reserve_huge(std::vector<T, A>& v, std::size_t n) {
  v.reserve(n);
  advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

/// v.assign(n, value) into storage advised for huge pages.
template <typename T, typename A>
void assign_huge(std::vector<T, A>& v, std::size_t n, const T& value) {
  v.clear();
  reserve_huge(v, n);
  v.assign(n, value);
}

}  // namespace cordgrasp::detail

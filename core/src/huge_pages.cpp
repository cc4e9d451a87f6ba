#include "huge_pages.h"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace cordgrasp::detail {

namespace {
constexpr std::uintptr_t kHugePageBytes = std::uintptr_t(2) << 20;  // x86-64 and arm64 (4 KiB base)
constexpr std::size_t kMinAdvisedBytes = std::size_t(8) << 20;
}  // namespace

void advise_huge_pages(const void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (p == nullptr || bytes < kMinAdvisedBytes) return;
  const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t first = (begin + kHugePageBytes - 1) & ~(kHugePageBytes - 1);
  const std::uintptr_t last = (begin + bytes) & ~(kHugePageBytes - 1);
  if (last <= first) return;
  // Advice only: a kernel without transparent huge pages answers EINVAL, and nothing changes.
  (void)madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}

}  // namespace cordgrasp::detail

#pragma once
// Private to core: a hint that memory at p is read soon (a cache line fetched ahead of a walk
// through an array much larger than the cache).

namespace cordgrasp::detail {

inline void prefetch(const void* p) {
#if defined(__x86_64__) && defined(__GNUC__)
  // GCC 12 drops __builtin_prefetch in some loops (the weld's); the instruction itself stays.
  asm volatile("prefetcht0 %0" : : "m"(*static_cast<const char*>(p)));
#else
  __builtin_prefetch(p);
#endif
}

}  // namespace cordgrasp::detail

#pragma once
// Allocator of the solver's big arrays (internal to lib/lbm): 2 MB aligned and marked for
// transparent huge pages (the kernel's default is often "madvise"). The sweep touches ~10
// pages per batch, whose TLB misses are expensive in a virtual machine (two-level page walks).
#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

#include <sys/mman.h>

namespace cmp::lbm {

template <class T>
struct HugePages {
  using value_type = T;
  HugePages() = default;
  template <class U>
  HugePages(const HugePages<U>&) {}
  T* allocate(std::size_t n) {
    constexpr std::size_t kHuge = std::size_t{2} << 20;
    const std::size_t bytes = (n * sizeof(T) + kHuge - 1) / kHuge * kHuge;
    void* p = std::aligned_alloc(kHuge, bytes);
    if (!p) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
    madvise(p, bytes, MADV_HUGEPAGE);
#endif
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t) { std::free(p); }
  template <class U>
  bool operator==(const HugePages<U>&) const { return true; }
};

template <class T>
using BigVector = std::vector<T, HugePages<T>>;

}  // namespace cmp::lbm

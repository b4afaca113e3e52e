#pragma once
/// \file
/// Cache-conscious layout and prefetching shared by the d-ary heaps (DaryHeap, IndexedDaryHeap).
///
/// ChildAlignedAllocator: for 0-based d-ary heap arrays, puts element 1 at the start of a cache
/// line. Why: children of i are d*i+1 ... d*i+d. With element 1 on a line boundary and d*sizeof(T)
/// dividing the line size, every node's children share one cache line; from the usual 16-byte
/// aligned allocation, half the 4-ary groups of doubles and every 8-ary group straddle two lines,
/// and a heap larger than the caches pays a second miss for them on each level of a pop
/// (LaMarca and Ladner, "The influence of caches on the performance of heaps", 1996).
///
/// HugePageAllocator (BigVector): arrays of several megabytes ask the kernel for 2 MiB pages.
/// Why: an event at 10^6 spheres reads a few dozen records scattered over 600 MB; with 4 KiB
/// pages nearly every one also misses the TLB (1536 entries cover 6 MB) and waits for a page
/// walk. Linux backs such memory with transparent huge pages only where madvise asks for them
/// (the usual default, `[madvise]` in /sys/kernel/mm/transparent_hugepage/enabled).

#include <cstddef>
#include <cstdint>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace collide::pq {

/// Cache-line size assumed for the layout (x86-64 and most ARM cores). Only a performance
/// assumption: a different line size changes speed, never results.
inline constexpr std::size_t heap_line_bytes = 64;

/// A transparent huge page on x86-64 and most ARM64 kernels.
inline constexpr std::size_t huge_page_bytes = std::size_t{2} << 20;

/// Arrays from this size on get huge pages (the rounding up to whole pages wastes less than half of
/// one). Several arrays of a few megabytes together outgrow the TLB's reach in 4 KiB pages: at
/// 10^5 discs the records (6.4 MB), the cold data and the calendar's entries (3.2 MB each) are
/// 3,200 small pages, and with them from 2 MiB on instead of 8 MiB the engine ran 1.09x (median of
/// nine interleaved pairs, issue 47, docs/benchmarks-history.md).
inline constexpr std::size_t huge_page_min_bytes = huge_page_bytes;

/// Storage for an array of `bytes` aligned to `alignment` (a power of two); from
/// huge_page_min_bytes on, whole huge pages that the kernel is advised to back as such. Only a
/// performance hint: where the advice is not taken the memory is the same, in small pages.
[[nodiscard]] inline void* allocate_array(std::size_t bytes, std::size_t alignment) {
    if (bytes < huge_page_min_bytes) return ::operator new (bytes, std::align_val_t{alignment});
    const std::size_t whole_pages = (bytes + huge_page_bytes - 1) & ~(huge_page_bytes - 1);
    void* p = ::operator new (whole_pages, std::align_val_t{huge_page_bytes});
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    (void)::madvise(p, whole_pages, MADV_HUGEPAGE);  // advice: a refusal changes nothing
#endif
    return p;
}

/// Frees what allocate_array(bytes, alignment) returned.
inline void deallocate_array(void* p, std::size_t bytes, std::size_t alignment) noexcept {
    const std::size_t used = bytes < huge_page_min_bytes ? alignment : huge_page_bytes;
    ::operator delete (p, std::align_val_t{used});
}

/// std::allocator with allocate_array's huge pages for big arrays.
template <class T>
class HugePageAllocator {
  public:
    using value_type = T;

    HugePageAllocator() noexcept = default;
    template <class U>
    explicit HugePageAllocator(const HugePageAllocator<U>& /*other*/) noexcept {}

    [[nodiscard]] T* allocate(std::size_t n) {
        return static_cast<T*>(allocate_array(n * sizeof(T), alignof(T)));
    }
    void deallocate(T* p, std::size_t n) noexcept {
        deallocate_array(p, n * sizeof(T), alignof(T));
    }

    template <class U>
    friend bool operator==(const HugePageAllocator& /*a*/,
                           const HugePageAllocator<U>& /*b*/) noexcept {
        return true;  // stateless: any instance frees what another allocated
    }
};

/// A vector of per-particle (or per-cell) records that may grow to hundreds of megabytes.
template <class T>
using BigVector = std::vector<T, HugePageAllocator<T>>;

template <class T>
class ChildAlignedAllocator {
  public:
    using value_type = T;

    ChildAlignedAllocator() noexcept = default;
    template <class U>
    explicit ChildAlignedAllocator(const ChildAlignedAllocator<U>& /*other*/) noexcept {}

    [[nodiscard]] T* allocate(std::size_t n) {
        auto* base = static_cast<std::byte*>(allocate_array(n * sizeof(T) + lead, heap_line_bytes));
        return reinterpret_cast<T*>(base + lead);  // storage of n T's: lead bytes past the line
    }

    void deallocate(T* p, std::size_t n) noexcept {
        deallocate_array(reinterpret_cast<std::byte*>(p) - lead, n * sizeof(T) + lead,
                         heap_line_bytes);
    }

    template <class U>
    friend bool operator==(const ChildAlignedAllocator& /*a*/,
                           const ChildAlignedAllocator<U>& /*b*/) noexcept {
        return true;  // stateless: any instance frees what another allocated
    }

  private:
    /// Bytes before element 0 within the first line, so that element 1 starts the next one.
    /// Items wider than a line cannot share lines anyway: they start on a line.
    static constexpr std::size_t lead =
        sizeof(T) < heap_line_bytes ? heap_line_bytes - sizeof(T) : 0;
    static_assert(lead % alignof(T) == 0, "the offset keeps T aligned");
};

/// Heaps whose items take more than this many bytes (a typical L2 cache) prefetch on their way
/// down; smaller ones are served from the caches, where the hints are pure overhead
/// (docs/benchmarks.md).
inline constexpr std::size_t heap_prefetch_bytes = std::size_t{1} << 20;

/// Which descendants of node i a sink prefetches in a heap beyond heap_prefetch_bytes: the items
/// `items` wide from i*items + offset, all of i's descendants some levels down, so the misses of
/// the coming levels overlap instead of following one another. At least two levels (the children
/// are being loaded anyway), more while they fit in two cache lines: a binary heap of doubles
/// looks four levels ahead (16 items), a 4-ary one two (16 items), an 8-ary one two (64 items).
struct HeapLookahead {
    std::size_t items = 0;   ///< d^levels; 0: no prefetching
    std::size_t offset = 0;  ///< index of node 0's first descendant at that depth
};

[[nodiscard]] constexpr HeapLookahead heap_lookahead(std::size_t d,
                                                     std::size_t item_bytes) noexcept {
    const std::size_t budget = 2 * heap_line_bytes / item_bytes;
    std::size_t items = d * d;
    while (items * d <= budget) items *= d;
    return {items, (items - 1) / (d - 1)};  // 1 + d + ... + d^(levels-1): the levels above
}

/// Asks the processor to load every cache line of the bytes [first, end) (end > first); no
/// effect on results. Always inlined into the sink loop that writes the heap: when the first
/// version of this hint loop was a separate function, GCC judged it free of side effects and
/// deleted every call (objdump found no prefetch instruction).
[[gnu::always_inline]] inline void prefetch_lines(std::uintptr_t first,
                                                  std::uintptr_t end) noexcept {
#if defined(__GNUC__)
    for (std::uintptr_t line = first & ~(heap_line_bytes - 1); line < end;
         line += heap_line_bytes) {
        __builtin_prefetch(reinterpret_cast<const void*>(line));
    }
#else
    (void)first, (void)end;
#endif
}

}  // namespace collide::pq

#pragma once
/// \file
/// An allocator for 0-based d-ary heap arrays that puts element 1 at the start of a cache line.
///
/// Why: children of i are d*i+1 ... d*i+d. With element 1 on a line boundary and d*sizeof(T)
/// dividing the line size, every node's children share one cache line; from the usual 16-byte
/// aligned allocation, half the 4-ary groups of doubles and every 8-ary group straddle two lines,
/// and a heap larger than the caches pays a second miss for them on each level of a pop
/// (LaMarca and Ladner, "The influence of caches on the performance of heaps", 1996).

#include <cstddef>
#include <new>

namespace collide::pq {

/// Cache-line size assumed for the layout (x86-64 and most ARM cores). Only a performance
/// assumption: a different line size changes speed, never results.
inline constexpr std::size_t heap_line_bytes = 64;

template <class T>
class ChildAlignedAllocator {
  public:
    using value_type = T;

    ChildAlignedAllocator() noexcept = default;
    template <class U>
    explicit ChildAlignedAllocator(const ChildAlignedAllocator<U>& /*other*/) noexcept {}

    [[nodiscard]] T* allocate(std::size_t n) {
        auto* base = static_cast<std::byte*>(::operator new(n * sizeof(T) + lead, line_alignment));
        return reinterpret_cast<T*>(base + lead);  // storage of n T's: lead bytes past the line
    }

    void deallocate(T* p, std::size_t /*n*/) noexcept {
        ::operator delete(reinterpret_cast<std::byte*>(p) - lead, line_alignment);
    }

    template <class U>
    friend bool operator==(const ChildAlignedAllocator& /*a*/,
                           const ChildAlignedAllocator<U>& /*b*/) noexcept {
        return true;  // stateless: any instance frees what another allocated
    }

  private:
    static constexpr std::align_val_t line_alignment{heap_line_bytes};

    /// Bytes before element 0 within the first line, so that element 1 starts the next one.
    /// Items wider than a line cannot share lines anyway: they start on a line.
    static constexpr std::size_t lead =
        sizeof(T) < heap_line_bytes ? heap_line_bytes - sizeof(T) : 0;
    static_assert(lead % alignof(T) == 0, "the offset keeps T aligned");
};

}  // namespace collide::pq

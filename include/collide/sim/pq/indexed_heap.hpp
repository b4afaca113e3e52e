#pragma once
/// \file
/// Indexed d-ary heap: items are stable handles 0..capacity-1 (particle ids) with a key each.
/// Beside the heap array `heap_` (handles in heap order) sits the position map `pos_`, keyed by
/// handle, so pos_[heap_[i]] == i and any handle is found in O(1); change_key, increase_key,
/// decrease_key and erase then run in O(d log_d N). The lecture keys its map by key value, which
/// breaks on duplicate keys; keying it by handle does not.
/// The keys are stored in heap order too (`keys_[i]` belongs to `heap_[i]`), not by handle: a
/// sink then compares d keys that sit next to each other in memory instead of d keys scattered
/// over the handle range (a cache miss each in a large heap).
/// Two layout choices for large heaps (the fast engine at 10^6 discs, where every level of a
/// sink below the cached top levels is a cache miss):
/// - The key array puts node 1 on a 64-byte boundary (ChildAlignedAllocator), so the D children
///   of a node share one cache line when D * sizeof(Key) == 64 (4-ary, 16-byte keys) instead of
///   straddling two lines for three nodes in four.
/// - Keys that name their own handle (HandleOf given: HandleOf{}(key) is the handle) need no
///   handle array: a sink then reads one line per level instead of two.
/// - Sinks in heaps beyond heap_prefetch_bytes prefetch the levels ahead (see sink), as
///   DaryHeap's pop does.
/// Obs (observer.hpp) sees every compare and exchange, and the removal of the last slot (a
/// removal moves the last entry into the hole: reported as an exchange, then the removal); the
/// default NoObserver costs nothing.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "collide/sim/pq/cache_layout.hpp"
#include "collide/sim/pq/observer.hpp"
#include "collide/sim/pq/order.hpp"

namespace collide::pq {

/// HandleOf = void: handles are stored beside the keys. Otherwise a function object with
/// `handle_type operator()(const Key&)` that reads the handle out of a key (the fast engine's
/// events name the disc that holds them); push and change_key then require HandleOf{}(k) == h.
template <class Key, Orientation O = Orientation::min, unsigned D = 4, class Less = std::less<Key>,
          class HandleOf = void, QueueObserver Obs = NoObserver>
class IndexedDaryHeap {
    static_assert(D >= 2, "a heap needs at least two children per node");
    static constexpr bool embedded = !std::is_void_v<HandleOf>;

  public:
    using handle_type = std::uint32_t;
    using key_type = Key;
    static constexpr unsigned arity = D;

    /// Sinks prefetch the levels ahead only in heaps whose keys take more than this many bytes.
    static constexpr std::size_t prefetch_bytes = heap_prefetch_bytes;

    /// An empty heap that accepts handles 0 .. capacity-1.
    explicit IndexedDaryHeap(std::size_t capacity = 0, Less less = Less{}, Obs obs = Obs{})
        : pos_(capacity, absent), less_(std::move(less)), obs_(std::move(obs)) {
        reserve_arrays(capacity);
    }

    [[nodiscard]] bool empty() const noexcept { return size() == 0; }
    [[nodiscard]] std::size_t size() const noexcept { return keys_.size(); }
    [[nodiscard]] std::size_t capacity() const noexcept { return pos_.size(); }

    /// Grows the handle range to 0 .. capacity-1 (never shrinks).
    void reserve_handles(std::size_t capacity) {
        if (capacity > pos_.size()) {
            pos_.resize(capacity, absent);
            reserve_arrays(capacity);
        }
    }

    /// A hint: asks the cache for h's slot of the position map. Changes nothing.
    void prefetch(handle_type h) const noexcept {
        if (h < pos_.size()) __builtin_prefetch(&pos_[h]);
    }
    [[nodiscard]] bool contains(handle_type h) const noexcept {
        return h < pos_.size() && pos_[h] != absent;
    }

    /// The key of a handle in the heap. Throws Error for an unknown handle.
    [[nodiscard]] const Key& key(handle_type h) const {
        require_contains(h, "key");
        return at(pos_[h]);
    }

    /// The handle that comes out next and its key. Precondition: !empty().
    [[nodiscard]] handle_type top() const { return handle_at(0); }
    [[nodiscard]] const Key& top_key() const { return at(0); }

    /// Inserts handle h with key k. Throws Error if h is out of range or already present (or,
    /// with HandleOf, if k names another handle).
    void push(handle_type h, Key k) {
        if (h >= pos_.size())
            throw_runtime_error("indexed heap: handle " + std::to_string(h) + " out of range");
        if (pos_[h] != absent)
            throw_runtime_error("indexed heap: handle " + std::to_string(h) + " already present");
        require_names(h, k);
        if constexpr (!embedded) heap_.push_back(h);
        keys_.push_back(k);
        swim(size() - 1, h, std::move(k));
        validate();
    }

    /// Removes and returns the handle that comes out next. Precondition: !empty().
    handle_type pop() {
        const handle_type h = handle_at(0);
        remove_at(0);
        validate();
        return h;
    }

    /// Sets the key of h, moving it up or down as needed. Throws Error for an unknown handle
    /// (or, with HandleOf, if k names another handle).
    void change_key(handle_type h, Key k) {
        require_contains(h, "change_key");
        require_names(h, k);
        const std::size_t i = pos_[h];
        obs_.compared(i, i);  // the new key against the old one, in slot i
        if (first(k, at(i))) {
            swim(i, h, std::move(k));
        } else {
            sink(i, h, std::move(k));
        }
        validate();
    }

    /// Inserts h with key k, or changes its key if present (the engines' "one pending event").
    void push_or_change(handle_type h, Key k) {
        if (contains(h)) {
            change_key(h, std::move(k));
        } else {
            push(h, std::move(k));
        }
    }

    /// Raises h's key under `Less` (k must not be less than the current key). Throws otherwise.
    void increase_key(handle_type h, Key k) {
        require_contains(h, "increase_key");
        obs_.compared(pos_[h], pos_[h]);  // the new key against the old one
        if (less_(k, at(pos_[h])))
            throw_runtime_error("indexed heap: increase_key given a smaller key");
        change_key(h, std::move(k));
    }

    /// Lowers h's key under `Less` (k must not be greater than the current key). Throws otherwise.
    void decrease_key(handle_type h, Key k) {
        require_contains(h, "decrease_key");
        obs_.compared(pos_[h], pos_[h]);
        if (less_(at(pos_[h]), k))
            throw_runtime_error("indexed heap: decrease_key given a larger key");
        change_key(h, std::move(k));
    }

    /// Removes h from the heap. Throws Error for an unknown handle.
    void erase(handle_type h) {
        require_contains(h, "erase");
        remove_at(pos_[h]);
        validate();
    }

    /// The key at position i of the heap array (0 comes out next), for traces that show only
    /// the first entries: O(1), unlike array(). Precondition: i < size().
    [[nodiscard]] const Key& key_at(std::size_t i) const noexcept { return at(i); }

    /// Handles in heap-array order, for traces and tests. O(N): builds a copy.
    [[nodiscard]] std::vector<handle_type> array() const {
        std::vector<handle_type> out(size());
        for (std::size_t i = 0; i < out.size(); ++i) out[i] = handle_at(i);
        return out;
    }

    /// Bytes held by the heap's arrays (capacities), for memory accounting.
    [[nodiscard]] std::size_t bytes() const noexcept {
        return (heap_.capacity() + pos_.capacity()) * sizeof(handle_type) +
               keys_.capacity() * sizeof(Key);
    }

    /// Heap order, and the position map is the inverse of the heap array: pos_[handle at i] == i
    /// for every i, and exactly size() handles are marked present. O(capacity).
    [[nodiscard]] bool check_invariants() const {
        if (!embedded && heap_.size() != size()) return false;
        std::size_t present = 0;
        for (handle_type p : pos_) present += (p != absent);
        if (present != size()) return false;
        for (std::size_t i = 0; i < size(); ++i) {
            const handle_type h = handle_at(i);
            if (h >= pos_.size() || pos_[h] != i) return false;
            if (i > 0 && first(at(i), at((i - 1) / D))) return false;
        }
        return true;
    }

  private:
    static constexpr handle_type absent = std::numeric_limits<handle_type>::max();

    [[nodiscard]] const Key& at(std::size_t i) const noexcept { return keys_[i]; }
    [[nodiscard]] Key& at(std::size_t i) noexcept { return keys_[i]; }
    [[nodiscard]] handle_type handle_at(std::size_t i) const noexcept {
        if constexpr (embedded) {
            return HandleOf{}(at(i));
        } else {
            return heap_[i];
        }
    }

    void reserve_arrays(std::size_t capacity) {
        if constexpr (!embedded) heap_.reserve(capacity);
        keys_.reserve(capacity);
    }

    void require_names([[maybe_unused]] handle_type h, [[maybe_unused]] const Key& k) const {
        if constexpr (embedded) {
            if (HandleOf{}(k) != h) {
                throw_runtime_error("indexed heap: the key given for handle " + std::to_string(h) +
                                    " names handle " + std::to_string(HandleOf{}(k)));
            }
        }
    }

    [[nodiscard]] bool first(const Key& a, const Key& b) const {
        return comes_first<O>(less_, a, b);
    }

    void require_contains(handle_type h, const char* op) const {
        if (!contains(h)) {
            throw_runtime_error(std::string("indexed heap: ") + op + " on handle " +
                                std::to_string(h) + " which is not in the heap");
        }
    }

    void place(std::size_t i, handle_type h, Key&& k) {
        if constexpr (!embedded) heap_[i] = h;
        at(i) = std::move(k);
        pos_[h] = static_cast<handle_type>(i);
    }

    /// Moves the entry at `from` into slot `to`.
    void move_entry(std::size_t to, std::size_t from) {
        place(to, handle_at(from), std::move(at(from)));
    }

    void remove_at(std::size_t i) {
        pos_[handle_at(i)] = absent;
        const std::size_t last = size() - 1;
        if (i == last) {
            if constexpr (!embedded) heap_.pop_back();
            keys_.pop_back();
            obs_.removed(last);
            return;
        }
        obs_.exchanged(i, last);
        obs_.removed(last);
        const handle_type moved = handle_at(last);
        Key k = std::move(at(last));
        if constexpr (!embedded) heap_.pop_back();
        keys_.pop_back();
        // The moved item may belong above or below its new slot.
        if (i > 0 && (obs_.compared(i, (i - 1) / D), first(k, at((i - 1) / D)))) {
            swim(i, moved, std::move(k));
        } else {
            sink(i, moved, std::move(k));
        }
    }

    /// Puts key k of handle h at or above slot i (whose contents may be overwritten).
    void swim(std::size_t i, handle_type h, Key k) {
        while (i > 0) {
            const std::size_t parent = (i - 1) / D;
            obs_.compared(i, parent);
            if (!first(k, at(parent))) break;
            obs_.exchanged(i, parent);
            move_entry(i, parent);
            i = parent;
        }
        place(i, h, std::move(k));
    }

    /// Puts key k of handle h at or below slot i (whose contents may be overwritten).
    ///
    /// In a heap larger than the caches every level below the cached top waits for a cache miss
    /// before it knows where to go next; so, as DaryHeap's pop does, each level asks for all of
    /// the node's descendants a few levels down (heap_lookahead) while its children are
    /// compared: the path continues among them, and the misses of the coming levels overlap
    /// instead of following one another (the fast engine re-keys a disc and sinks it from the
    /// root at every event; docs/benchmarks.md). Heaps in the caches skip the hints.
    // Always inlined: the fast engine sinks a re-keyed disc at every event, and GCC stopped
    // inlining this call once the engine became a template over the dimension (+12 M
    // instructions per 2 x 10^5 collisions, docs/benchmarks.md).
    [[gnu::always_inline]] void sink(std::size_t i, handle_type h, Key k) {
        const std::size_t n = size();
        const HeapLookahead ahead = n * sizeof(Key) > heap_prefetch_bytes
                                        ? heap_lookahead(D, sizeof(Key))
                                        : HeapLookahead{};
        for (;;) {
            const std::size_t c0 = D * i + 1;
            if (c0 >= n) break;
            const std::size_t below = i * ahead.items + ahead.offset;
            if (ahead.items != 0 && below < n) {
                prefetch_lines(address_of(below), address_of(std::min(n, below + ahead.items)));
            }
            const std::size_t c_end = c0 + D < n ? c0 + D : n;
            std::size_t best = c0;
            for (std::size_t c = c0 + 1; c < c_end; ++c) {
                obs_.compared(c, best);
                if (first(at(c), at(best))) best = c;
            }
            obs_.compared(i, best);
            if (!first(at(best), k)) break;
            obs_.exchanged(i, best);
            move_entry(i, best);
            i = best;
        }
        place(i, h, std::move(k));
    }

    /// Address of node i's key slot (i may be size(): one past the last).
    [[nodiscard]] std::uintptr_t address_of(std::size_t i) const noexcept {
        return reinterpret_cast<std::uintptr_t>(keys_.data() + i);
    }

    void validate() const {
        if constexpr (validate_heaps)
            require_invariant(check_invariants(), "indexed heap order / position map");
    }

    std::vector<handle_type> heap_;  ///< handles in heap order (unused when keys name them)
    BigVector<handle_type> pos_;     ///< pos_[handle] = index in heap order, or `absent`
    /// Keys in heap order (node 1 starts a cache line, so each node's children share lines).
    std::vector<Key, ChildAlignedAllocator<Key>> keys_;
    [[no_unique_address]] Less less_;
    [[no_unique_address]] Obs obs_;
};

}  // namespace collide::pq

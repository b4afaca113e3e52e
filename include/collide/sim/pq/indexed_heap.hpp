#pragma once
/// \file
/// Indexed d-ary heap: items are stable handles 0..capacity-1 (particle ids) with a key each.
/// Beside the heap array `heap_` (handles in heap order) sits the position map `pos_`, keyed by
/// handle, so pos_[heap_[i]] == i and any handle is found in O(1); change_key, increase_key,
/// decrease_key and erase then run in O(d log_d N). The lecture keys its map by key value, which
/// breaks on duplicate keys; keying it by handle does not.
/// The keys are stored in heap order too (`keys_[i]` belongs to `heap_[i]`), not by handle: a
/// sink then compares d keys that sit next to each other in memory instead of d keys scattered
/// over the handle range (a cache miss each). For the fast engine at 10^5 discs this halved the
/// heap's share of the run time.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "collide/sim/pq/order.hpp"

namespace collide::pq {

template <class Key, Orientation O = Orientation::min, unsigned D = 4, class Less = std::less<Key>>
class IndexedDaryHeap {
    static_assert(D >= 2, "a heap needs at least two children per node");

public:
    using handle_type = std::uint32_t;
    using key_type = Key;
    static constexpr unsigned arity = D;

    /// An empty heap that accepts handles 0 .. capacity-1.
    explicit IndexedDaryHeap(std::size_t capacity = 0, Less less = Less{})
        : pos_(capacity, absent), less_(std::move(less)) {
        heap_.reserve(capacity);
        keys_.reserve(capacity);
    }

    [[nodiscard]] bool empty() const noexcept { return heap_.empty(); }
    [[nodiscard]] std::size_t size() const noexcept { return heap_.size(); }
    [[nodiscard]] std::size_t capacity() const noexcept { return pos_.size(); }

    /// Grows the handle range to 0 .. capacity-1 (never shrinks).
    void reserve_handles(std::size_t capacity) {
        if (capacity > pos_.size()) {
            pos_.resize(capacity, absent);
            heap_.reserve(capacity);
            keys_.reserve(capacity);
        }
    }

    [[nodiscard]] bool contains(handle_type h) const noexcept {
        return h < pos_.size() && pos_[h] != absent;
    }

    /// The key of a handle in the heap. Throws Error for an unknown handle.
    [[nodiscard]] const Key& key(handle_type h) const {
        require_contains(h, "key");
        return keys_[pos_[h]];
    }

    /// The handle that comes out next and its key. Precondition: !empty().
    [[nodiscard]] handle_type top() const { return heap_.front(); }
    [[nodiscard]] const Key& top_key() const { return keys_.front(); }

    /// Inserts handle h with key k. Throws Error if h is out of range or already present.
    void push(handle_type h, Key k) {
        if (h >= pos_.size()) throw_runtime_error("indexed heap: handle " + std::to_string(h) + " out of range");
        if (pos_[h] != absent) throw_runtime_error("indexed heap: handle " + std::to_string(h) + " already present");
        heap_.push_back(h);
        keys_.push_back(k);
        swim(heap_.size() - 1, std::move(k));
        validate();
    }

    /// Removes and returns the handle that comes out next. Precondition: !empty().
    handle_type pop() {
        const handle_type h = heap_.front();
        remove_at(0);
        validate();
        return h;
    }

    /// Sets the key of h, moving it up or down as needed. Throws Error for an unknown handle.
    void change_key(handle_type h, Key k) {
        require_contains(h, "change_key");
        const std::size_t i = pos_[h];
        if (first(k, keys_[i])) {
            swim(i, std::move(k));
        } else {
            sink(i, std::move(k));
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
        if (less_(k, keys_[pos_[h]])) throw_runtime_error("indexed heap: increase_key given a smaller key");
        change_key(h, std::move(k));
    }

    /// Lowers h's key under `Less` (k must not be greater than the current key). Throws otherwise.
    void decrease_key(handle_type h, Key k) {
        require_contains(h, "decrease_key");
        if (less_(keys_[pos_[h]], k)) throw_runtime_error("indexed heap: decrease_key given a larger key");
        change_key(h, std::move(k));
    }

    /// Removes h from the heap. Throws Error for an unknown handle.
    void erase(handle_type h) {
        require_contains(h, "erase");
        remove_at(pos_[h]);
        validate();
    }

    /// Handles in heap-array order, for traces and tests.
    [[nodiscard]] const std::vector<handle_type>& array() const noexcept { return heap_; }

    /// Bytes held by the heap's arrays (capacities), for memory accounting.
    [[nodiscard]] std::size_t bytes() const noexcept {
        return (heap_.capacity() + pos_.capacity()) * sizeof(handle_type) + keys_.capacity() * sizeof(Key);
    }

    /// Heap order, and the position map is the inverse of the heap array:
    /// pos_[heap_[i]] == i for every i, and exactly size() handles are marked present. O(capacity).
    [[nodiscard]] bool check_invariants() const {
        if (keys_.size() != heap_.size()) return false;
        std::size_t present = 0;
        for (handle_type p : pos_) present += (p != absent);
        if (present != heap_.size()) return false;
        for (std::size_t i = 0; i < heap_.size(); ++i) {
            if (heap_[i] >= pos_.size() || pos_[heap_[i]] != i) return false;
            if (i > 0 && first(keys_[i], keys_[(i - 1) / D])) return false;
        }
        return true;
    }

private:
    static constexpr handle_type absent = std::numeric_limits<handle_type>::max();

    [[nodiscard]] bool first(const Key& a, const Key& b) const { return comes_first<O>(less_, a, b); }

    void require_contains(handle_type h, const char* op) const {
        if (!contains(h)) {
            throw_runtime_error(std::string("indexed heap: ") + op + " on handle " + std::to_string(h) +
                                " which is not in the heap");
        }
    }

    void place(std::size_t i, handle_type h, Key&& k) {
        heap_[i] = h;
        keys_[i] = std::move(k);
        pos_[h] = static_cast<handle_type>(i);
    }

    /// Moves the entry at `from` into slot `to`.
    void move_entry(std::size_t to, std::size_t from) { place(to, heap_[from], std::move(keys_[from])); }

    void remove_at(std::size_t i) {
        const handle_type h = heap_[i];
        pos_[h] = absent;
        const std::size_t last = heap_.size() - 1;
        if (i == last) {
            heap_.pop_back();
            keys_.pop_back();
            return;
        }
        const handle_type moved = heap_[last];
        Key k = std::move(keys_[last]);
        heap_.pop_back();
        keys_.pop_back();
        heap_[i] = moved;  // sink/swim place it for real
        // The moved item may belong above or below its new slot.
        if (i > 0 && first(k, keys_[(i - 1) / D])) {
            swim(i, std::move(k));
        } else {
            sink(i, std::move(k));
        }
    }

    /// Puts key k (of the handle at heap_[i]) at or above slot i.
    void swim(std::size_t i, Key k) {
        const handle_type h = heap_[i];
        while (i > 0) {
            const std::size_t parent = (i - 1) / D;
            if (!first(k, keys_[parent])) break;
            move_entry(i, parent);
            i = parent;
        }
        place(i, h, std::move(k));
    }

    /// Puts key k (of the handle at heap_[i]) at or below slot i.
    void sink(std::size_t i, Key k) {
        const std::size_t n = heap_.size();
        const handle_type h = heap_[i];
        for (;;) {
            const std::size_t c0 = D * i + 1;
            if (c0 >= n) break;
            const std::size_t c_end = c0 + D < n ? c0 + D : n;
            std::size_t best = c0;
            for (std::size_t c = c0 + 1; c < c_end; ++c) {
                if (first(keys_[c], keys_[best])) best = c;
            }
            if (!first(keys_[best], k)) break;
            move_entry(i, best);
            i = best;
        }
        place(i, h, std::move(k));
    }

    void validate() const {
        if constexpr (validate_heaps) require_invariant(check_invariants(), "indexed heap order / position map");
    }

    std::vector<handle_type> heap_;  ///< handles in heap order
    std::vector<handle_type> pos_;   ///< pos_[handle] = index in heap_, or `absent`
    std::vector<Key> keys_;          ///< keys_[i] is the key of heap_[i] (heap order)
    [[no_unique_address]] Less less_;
};

}  // namespace collide::pq

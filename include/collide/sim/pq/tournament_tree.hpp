#pragma once
/// \file
/// Indexed tournament (winner) tree: one leaf per handle at a fixed place, every inner node the
/// earliest key of its subtree (Marin, Risso and Cordero, "Efficient algorithms for many-body
/// hard particle molecular dynamics", J. Comput. Phys. 109, 1993). An event queue with one
/// pending event per particle, as the fast engine keeps.
///
/// Against the indexed heap it needs no position map (handle h's leaf is node `inner + h`), and
/// handles numbered in space-filling-curve order put the leaves of neighbouring particles side
/// by side: a collision re-keys particles whose paths to the root share their lower nodes. The
/// tree is 4-ary with node 1 on a cache line (ChildAlignedAllocator), so with 16-byte keys a
/// node's four children are one line. A change of key replays its path upwards and stops at the
/// first node whose winner neither changes nor was the changed handle.
///
/// Key needs a `double t` member, the event time; a leaf with t = +infinity is empty (push and
/// push_or_change refuse such keys; erase writes one). Keys of equal finite time are ordered by
/// Less (a strict total order: the pops come out as from a heap under the same Less); empty
/// leaves are never given to Less. HandleOf{}(key) names the handle that holds the key.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "collide/error.hpp"
#include "collide/sim/pq/cache_layout.hpp"
#include "collide/sim/pq/order.hpp"

namespace collide::pq {

template <class Key, class Less, class HandleOf>
class TournamentTree {
  public:
    using handle_type = std::uint32_t;
    static constexpr std::size_t arity = 4;

    explicit TournamentTree(std::size_t capacity = 0, Less less = Less{}) : less_(std::move(less)) {
        build(capacity);
    }

    /// Grows the handle range to 0 .. capacity-1 (never shrinks), keeping the entries.
    void reserve_handles(std::size_t capacity) {
        if (capacity <= capacity_) return;
        std::vector<Key> kept;
        kept.reserve(size_);
        for_each([&](handle_type, const Key& k) { kept.push_back(k); });
        build(capacity);
        for (const Key& k : kept) push_or_change(HandleOf{}(k), k);
    }

    /// Empties the tree and frees its nodes (no handles until reserve_handles).
    void release() {
        decltype(nodes_)().swap(nodes_);
        build(0);
    }

    [[nodiscard]] bool empty() const noexcept { return size_ == 0; }
    [[nodiscard]] std::size_t size() const noexcept { return size_; }
    [[nodiscard]] std::size_t capacity() const noexcept { return capacity_; }

    [[nodiscard]] bool contains(handle_type h) const noexcept {
        return h < capacity_ && is_entry(leaf(h));
    }

    /// The key of a handle in the tree. Throws Error for an unknown handle.
    [[nodiscard]] const Key& key(handle_type h) const {
        if (!contains(h)) refuse("key", h);
        return leaf(h);
    }

    /// True when the tree holds an entry (the calendar's settle(), for the same loop).
    bool settle() const noexcept { return size_ > 0; }
    /// The earliest entry's handle and key. Precondition: !empty().
    [[nodiscard]] handle_type top() const noexcept { return HandleOf{}(nodes_[0]); }
    [[nodiscard]] const Key& top_key() const noexcept { return nodes_[0]; }

    /// Inserts h with key k, or changes its key. Throws Error for a handle out of range, a key
    /// that names another handle or a time that is not below +infinity.
    [[gnu::always_inline]] void push_or_change(handle_type h, const Key& k) {
        if (h >= capacity_ || HandleOf{}(k) != h || !(k.t < empty_time)) refuse_push(h, k);
        size_ += !is_entry(leaf(h));
        replay(h, k);
        validate();
    }

    /// Removes h's entry. Throws Error for an unknown handle.
    void erase(handle_type h) {
        if (!contains(h)) refuse("erase", h);
        Key gone = leaf(h);  // keeps h as the empty leaf's owner, for replay's test
        gone.t = empty_time;
        --size_;
        replay(h, gone);
        validate();
    }

    /// Calls visit(handle, key) for every entry, in handle order.
    template <class Visit>
    void for_each(Visit&& visit) const {
        for (std::size_t h = 0; h < capacity_; ++h) {
            const Key& k = nodes_[inner_ + h];
            if (is_entry(k)) visit(static_cast<handle_type>(h), k);
        }
    }

    [[nodiscard]] std::size_t bytes() const noexcept { return nodes_.capacity() * sizeof(Key); }

    /// Every inner node holds the earliest of its children (the same key, bit for bit in time
    /// and handle), each entry sits at its handle's leaf, and size() counts the entries.
    /// O(capacity).
    [[nodiscard]] bool check_invariants() const {
        std::size_t entries = 0;
        for (std::size_t h = 0; h < capacity_; ++h) {
            const Key& k = nodes_[inner_ + h];
            if (!is_entry(k)) continue;
            ++entries;
            if (HandleOf{}(k) != h) return false;
        }
        if (entries != size_) return false;
        for (std::size_t i = 0; i < inner_; ++i) {
            const Key& best = nodes_[earliest_child(i)];
            const Key& kept = nodes_[i];
            if (is_entry(best) != is_entry(kept)) return false;
            if (is_entry(best) && (best.t != kept.t || HandleOf{}(best) != HandleOf{}(kept)))
                return false;
        }
        return true;
    }

  private:
    static constexpr double empty_time = std::numeric_limits<double>::infinity();
    static_assert(arity == 4, "replay finds a node's siblings by masks of 3");
    /// Levels above a leaf whose lines replay asks for before it starts (the ones below the
    /// levels that every event touches, at 10^5 handles and more).
    static constexpr std::size_t prefetch_levels = 4;

    [[nodiscard]] static bool is_entry(const Key& k) noexcept { return k.t < empty_time; }

    /// a before b: earlier time, or the same finite time and Less (empty leaves tie).
    [[nodiscard]] bool first(const Key& a, const Key& b) const {
        return a.t < b.t || (a.t == b.t && a.t < empty_time && less_(a, b));
    }

    [[nodiscard]] const Key& leaf(handle_type h) const noexcept { return nodes_[inner_ + h]; }

    /// Leaves for `capacity` handles (at least one, and one more than a multiple of 3, so that
    /// every inner node has four children), all empty.
    void build(std::size_t capacity) {
        std::size_t leaves = capacity > 0 ? capacity : 1;
        leaves += (arity - 1 - (leaves - 1) % (arity - 1)) % (arity - 1);
        inner_ = (leaves - 1) / (arity - 1);
        capacity_ = capacity;
        size_ = 0;
        Key none{};
        none.t = empty_time;
        nodes_.assign(inner_ + leaves, none);
    }

    [[nodiscard]] std::size_t earliest_child(std::size_t i) const {
        const std::size_t c0 = arity * i + 1;
        return earlier(earlier(c0, c0 + 1), earlier(c0 + 2, c0 + 3));
    }

    /// The node of x and y that holds the earlier key. Times that differ (nearly always) are
    /// chosen without a branch: a branch on the time compare, whose outcome is random, was
    /// mispredicted half of the time. Equal times (ties, or two empty leaves) go to Less.
    [[nodiscard]] std::size_t earlier(std::size_t x, std::size_t y) const {
        const double tx = nodes_[x].t;
        const double ty = nodes_[y].t;
        if (tx == ty) [[unlikely]] {
            return tx < empty_time && less_(nodes_[y], nodes_[x]) ? y : x;
        }
        const std::size_t y_first = std::size_t{0} - static_cast<std::size_t>(ty < tx);
        return x ^ ((x ^ y) & y_first);
    }

    /// Writes k at h's leaf and replays the matches above it; `rising`, the new winner of the
    /// child below, is also stored at that child. Where the node's winner was h's old key, the
    /// winner is the earlier of `rising` and the earliest of its three siblings (one cache line
    /// with it; their loads do not wait for the levels below), chosen without a branch on the
    /// times; elsewhere `rising` wins only if it beats the node's winner, and the replay ends
    /// where it does not. The path's lower lines are asked for first: it is known from h alone.
    [[gnu::always_inline]] void replay(handle_type h, const Key& k) {
        std::size_t node = inner_ + h;
        for (std::size_t up = node, level = 0; up > 0 && level < prefetch_levels; ++level) {
            up = (up - 1) / arity;
            __builtin_prefetch(&nodes_[up]);
        }
        nodes_[node] = k;
        Key rising = k;
        while (node > 0) {
            const std::size_t parent = (node - 1) / arity;
            Key& winner = nodes_[parent];
            if (HandleOf{}(winner) == h) {
                const std::size_t c0 = arity * parent + 1;
                const std::size_t me = node - c0;
                const std::size_t sibling =
                    earlier(earlier(c0 + ((me + 1) & 3), c0 + ((me + 2) & 3)), c0 + ((me + 3) & 3));
                rising = nodes_[earlier(node, sibling)];
            } else if (!first(rising, winner)) {
                return;
            }
            winner = rising;
            node = parent;
        }
    }

    [[noreturn]] static void refuse(const char* op, handle_type h) {
        throw_runtime_error(std::string("tournament tree: ") + op + " on handle " +
                            std::to_string(h) + " which is not in the tree");
    }

    [[noreturn]] void refuse_push(handle_type h, const Key& k) const {
        if (h >= capacity_) {
            throw_runtime_error("tournament tree: handle " + std::to_string(h) + " out of range");
        }
        if (HandleOf{}(k) != h) {
            throw_runtime_error("tournament tree: the key given for handle " + std::to_string(h) +
                                " names handle " + std::to_string(HandleOf{}(k)));
        }
        throw_runtime_error("tournament tree: handle " + std::to_string(h) +
                            " given a key time that is not below +infinity");
    }

    /// After every mutation when COLLIDE_VALIDATE is on (see pq::require_invariant).
    void validate() const {
        if constexpr (validate_heaps) {
            require_invariant(check_invariants(), "tournament tree winners");
        }
    }

    /// Inner nodes 0 .. inner_-1 in heap order (children of i: 4i+1 .. 4i+4), then one leaf per
    /// handle; node 1 starts a cache line.
    std::vector<Key, ChildAlignedAllocator<Key>> nodes_;
    std::size_t inner_ = 0;
    std::size_t capacity_ = 0;
    std::size_t size_ = 0;
    [[no_unique_address]] Less less_;
};

}  // namespace collide::pq

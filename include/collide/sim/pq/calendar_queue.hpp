#pragma once
/// \file
/// Event calendar: an indexed priority queue of timed events, one per handle, for a simulation
/// whose events are popped in time order and mostly rescheduled far ahead of the clock (R. Brown,
/// "Calendar queues", CACM 31, 1988; the form here is the one of Smallenburg's hard-sphere code,
/// Eur. Phys. J. E 45, 22, 2022).
///
/// Time is cut into blocks of equal width. Events of the current block and earlier sit in a
/// small indexed 4-ary heap (ordered by Less, so ties fall exactly as in one big heap); events
/// of the next `buckets - 1` blocks sit unordered in one doubly linked list per block (a ring of
/// buckets); later ones in an overflow list that is sorted into the ring once per lap. When the
/// heap runs dry the next block's list moves into it. A change of key is then O(1) for an event
/// moved beyond the current block (the common case: a particle's next event lies many blocks
/// ahead), and the heap's sinks are short (it holds a few dozen events, not N).
///
/// Pop order is the same as a single heap's under the same Less: the heap always holds every
/// event of the blocks up to the current one, and the other events are later than all of them
/// (block_of is monotone in time). A width of +infinity keeps everything in the heap.
///
/// Key needs a `double t` member (the event time, never NaN); HandleOf{}(key) names the
/// handle that holds the key (IndexedDaryHeap's embedded handles).

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "collide/sim/pq/cache_layout.hpp"
#include "collide/sim/pq/indexed_heap.hpp"

namespace collide::pq {

template <class Key, class Less, class HandleOf>
class CalendarQueue {
  public:
    using handle_type = std::uint32_t;
    using Heap = IndexedDaryHeap<Key, Orientation::min, 4, Less, HandleOf>;

    explicit CalendarQueue(std::size_t capacity = 0, Less less = Less{})
        : heap_(capacity, std::move(less)), entry_(capacity) {}

    void reserve_handles(std::size_t capacity) {
        heap_.reserve_handles(capacity);
        if (inv_width_ != 0.0 && capacity > entry_.size()) entry_.resize(capacity);
    }

    /// Blocks of `width` (> 0; +infinity: one block, a plain heap, which frees the lists'
    /// entries: 32 bytes per handle) and a ring of `buckets` lists (at least 2, rounded up to a
    /// power of two, so that a block's bucket is a mask and not a division), the current block
    /// being the one of time `now`. Re-files every entry.
    void tune(double width, std::size_t buckets, double now) {
        std::vector<std::pair<handle_type, Key>> all;
        all.reserve(size());
        for_each([&](handle_type h, const Key& k) { all.emplace_back(h, k); });
        for (const auto& [h, k] : all) erase(h);
        if (std::isinf(width)) {
            BigVector<Entry>().swap(entry_);  // one block files nothing in the lists
        } else if (entry_.size() < heap_.capacity()) {
            entry_.resize(heap_.capacity());
        }
        inv_width_ = std::isinf(width) ? 0.0 : 1.0 / width;
        ring_.assign(std::bit_ceil(std::max<std::size_t>(buckets, 2)), none);
        ring_mask_ = ring_.size() - 1;
        walk_ahead_ = !std::isinf(width) && entry_.size() * sizeof(Entry) > walk_ahead_bytes;
        ahead_ = none;
        cur_ = 0;
        cur_ = block_of(now);
        for (const auto& [h, k] : all) place(h, k);
        validate();
    }

    [[nodiscard]] bool empty() const noexcept { return size() == 0; }
    [[nodiscard]] std::size_t size() const noexcept { return heap_.size() + far_count_; }
    [[nodiscard]] bool contains(handle_type h) const noexcept {
        return heap_.contains(h) || in_lists(h);
    }
    [[nodiscard]] const Key& key(handle_type h) const {
        return heap_.contains(h) ? heap_.key(h) : entry_[h].key;
    }

    /// Brings the earliest event to the heap's top; false when the calendar is empty. Call it
    /// before top() and top_key() (a const calendar may hold its earliest event in a list).
    /// `on_ahead(handle, key)` sees, while entries are walked ahead (see step_ahead), each event
    /// of the next block, about a block of events before its turn: a caller may ask the cache
    /// for what that event will read.
    template <class OnAhead>
    bool settle(OnAhead&& on_ahead) {
        if (walk_ahead_) step_ahead(on_ahead);
        while (heap_.empty()) {
            if (far_count_ == 0) return false;
            if (ring_count_ > 0) {
                advance_to_block(cur_ + 1, false);
            } else {
                advance_to_block(earliest_overflow_block(), true);
            }
            validate();
        }
        return true;
    }
    bool settle() {
        return settle([](handle_type, const Key&) {});
    }
    [[nodiscard]] handle_type top() const { return heap_.top(); }
    [[nodiscard]] const Key& top_key() const { return heap_.top_key(); }

    // Always inlined, as the heap's sink is: out of line, the heap's change_key was no longer
    // inlined either, 4 % more instructions per 2D event at 10^5 discs (cachegrind).
    [[gnu::always_inline]] void push_or_change(handle_type h, const Key& k) {
        if (inv_width_ == 0.0) {
            heap_.push_or_change(h, k);
            validate();
            return;
        }
        if (heap_.contains(h)) {
            if (block_of(k.t) <= cur_) {
                heap_.change_key(h, k);
                return;
            }
            heap_.erase(h);
        } else if (in_lists(h)) {
            unlink(h);
        }
        place(h, k);
        validate();
    }

    /// A hint that h's key will soon be t: asks the cache for what filing it writes when it goes
    /// to the ring (its bucket's head and h's entry). Changes nothing.
    void prefetch_place(handle_type h, double t) const noexcept {
        if (inv_width_ == 0.0) return;
        const std::int64_t b = block_of(t);
        if (b <= cur_ || b - cur_ >= static_cast<std::int64_t>(ring_.size())) return;
        __builtin_prefetch(&ring_[bucket_of(b)], 1);
        __builtin_prefetch(&entry_[h], 1);
    }

    /// A hint that h's key will soon change: asks the cache for h's position-map slot and
    /// entry. Changes nothing.
    void prefetch_handle(handle_type h) const noexcept {
        heap_.prefetch(h);
        if (h < entry_.size()) __builtin_prefetch(&entry_[h], 1);
    }

    /// A hint, some time after prefetch_handle(h): asks for the neighbours that unlinking h
    /// from its list writes (each a miss of its own past the caches). Changes nothing.
    void prefetch_unlink(handle_type h) const noexcept {
        if (!in_lists(h)) return;
        const Entry& e = entry_[h];
        if (e.prev < entry_.size()) __builtin_prefetch(&entry_[e.prev], 1);
        if (e.next < entry_.size()) __builtin_prefetch(&entry_[e.next], 1);
    }

    void erase(handle_type h) {
        if (heap_.contains(h)) {
            heap_.erase(h);
        } else if (in_lists(h)) {
            unlink(h);
        }
        validate();
    }

    /// Calls visit(handle, key) for every entry: the heap's in heap order, then the lists'.
    template <class Visit>
    void for_each(Visit&& visit) const {
        for (std::size_t k = 0; k < heap_.size(); ++k) {
            const Key& key = heap_.key_at(k);
            visit(HandleOf{}(key), key);
        }
        for (handle_type first : ring_) {
            for (handle_type h = first; h != none; h = entry_[h].next) visit(h, entry_[h].key);
        }
        for (handle_type h = overflow_; h != none; h = entry_[h].next) visit(h, entry_[h].key);
    }

    /// The heap of the current block (its top is the earliest event after settle()).
    [[nodiscard]] const Heap& near() const noexcept { return heap_; }

    /// Buckets in the ring (a power of two).
    [[nodiscard]] std::size_t buckets() const noexcept { return ring_.size(); }

    [[nodiscard]] std::size_t bytes() const noexcept {
        return heap_.bytes() + entry_.capacity() * sizeof(Entry) +
               ring_.capacity() * sizeof(handle_type);
    }

    /// The heap's invariants; heap entries in blocks up to the current one, list entries after
    /// it, each ring entry in the bucket of its block, links that go both ways, counts that add
    /// up.
    [[nodiscard]] bool check_invariants() const {
        if (!heap_.check_invariants()) return false;
        for (std::size_t k = 0; k < heap_.size(); ++k) {
            const Key& key = heap_.key_at(k);
            const handle_type h = HandleOf{}(key);
            if (block_of(key.t) > cur_ || (h < entry_.size() && entry_[h].slot != none)) {
                return false;
            }
        }
        std::size_t ring_seen = 0;
        for (std::size_t s = 0; s < ring_.size(); ++s) {
            handle_type prev = none;
            for (handle_type h = ring_[s]; h != none; h = entry_[h].next) {
                const Entry& e = entry_[h];
                const std::int64_t b = block_of(e.key.t);
                if (e.slot != s || e.prev != prev || b <= cur_ ||
                    b >= cur_ + static_cast<std::int64_t>(ring_.size()) || bucket_of(b) != s ||
                    heap_.contains(h)) {
                    return false;
                }
                prev = h;
                ++ring_seen;
            }
        }
        std::size_t overflow_seen = 0;
        handle_type prev = none;
        for (handle_type h = overflow_; h != none; h = entry_[h].next) {
            const Entry& e = entry_[h];
            if (e.slot != overflow_slot || e.prev != prev || block_of(e.key.t) <= cur_)
                return false;
            prev = h;
            ++overflow_seen;
        }
        return ring_seen == ring_count_ && overflow_seen == far_count_ - ring_count_;
    }

  private:
    static constexpr handle_type none = std::numeric_limits<handle_type>::max();
    static constexpr handle_type overflow_slot = none - 1;
    /// Entries past this many bytes (32,768 handles) are walked ahead (see step_ahead): on the
    /// 2-core machine of 2026-11-30 that gained 1.11x at 10^5 discs (3.2 MB of entries), 1.03x
    /// at 5 x 10^4 and 1.22x at 10^6; at 10^3 and 10^4 it was level, and is left off.
    static constexpr std::size_t walk_ahead_bytes = std::size_t{1} << 20;
    /// Blocks beyond this are all filed as the last one (times near the double range's end).
    static constexpr double max_block = 4.0e18;

    /// A handle's entry when its event is in a list (slot: bucket, overflow_slot or none).
    struct Entry {
        Key key{};
        handle_type next = none;
        handle_type prev = none;
        handle_type slot = none;
    };

    /// True when h's entry is in the ring or the overflow list (one block keeps no entries).
    [[nodiscard]] bool in_lists(handle_type h) const noexcept {
        return h < entry_.size() && entry_[h].slot != none;
    }

    /// Monotone in t: t * (1 / width) rounds monotonically and floor keeps the order.
    [[nodiscard]] std::int64_t block_of(double t) const noexcept {
        const double x = t * inv_width_;
        if (!(x > 0.0)) return 0;
        if (!(x < max_block)) return static_cast<std::int64_t>(max_block);
        return static_cast<std::int64_t>(x);
    }

    /// The ring's bucket of block b (b >= 0).
    [[nodiscard]] std::size_t bucket_of(std::int64_t b) const noexcept {
        return static_cast<std::size_t>(b) & ring_mask_;
    }

    /// Files an entry that is in no structure: the heap up to the current block, the ring for
    /// the next buckets - 1 blocks, the overflow list after.
    void place(handle_type h, const Key& k) {
        const std::int64_t b = block_of(k.t);
        if (b <= cur_) {
            heap_.push(h, k);
            return;
        }
        entry_[h].key = k;
        if (b - cur_ < static_cast<std::int64_t>(ring_.size())) {
            const auto s = static_cast<handle_type>(bucket_of(b));
            link(h, s, ring_[s]);
            ++ring_count_;
        } else {
            link(h, overflow_slot, overflow_);
        }
        ++far_count_;
    }

    void link(handle_type h, handle_type slot, handle_type& head) noexcept {
        Entry& e = entry_[h];
        e.slot = slot;
        e.prev = none;
        e.next = head;
        if (head != none) entry_[head].prev = h;
        head = h;
    }

    void unlink(handle_type h) noexcept {
        Entry& e = entry_[h];
        handle_type& head = e.slot == overflow_slot ? overflow_ : ring_[e.slot];
        if (e.prev != none) {
            entry_[e.prev].next = e.next;
        } else {
            head = e.next;
        }
        if (e.next != none) entry_[e.next].prev = e.prev;
        if (e.slot != overflow_slot) --ring_count_;
        --far_count_;
        e.slot = none;
    }

    /// Makes block b current (b > cur_): once per lap of the ring, the overflow list is filed
    /// again (an overflow entry's block lies at least one lap ahead when it is filed, so it is
    /// back in the ring or the heap before its block comes); then block b's bucket moves into
    /// the heap. A jump over an empty ring (`refile`) files the overflow list again in any case.
    void advance_to_block(std::int64_t b, bool refile) {
        const auto lap = [&](std::int64_t x) {
            return x / static_cast<std::int64_t>(ring_.size());
        };
        refile = refile || lap(b) != lap(cur_);
        cur_ = b;
        if (refile) {
            take_list(overflow_, [&](handle_type h) { place(h, entry_[h].key); });
        }
        const std::size_t slot = bucket_of(b);
        take_list(ring_[slot], [&](handle_type h) {
            --ring_count_;
            heap_.push(h, entry_[h].key);
        });
        if (walk_ahead_) {
            // The next bucket's list is walked one entry per event while this block's events
            // run, and the bucket after it asked for (see step_ahead).
            ahead_ = ring_[bucket_of(b + 1)];
            if (ahead_ != none) __builtin_prefetch(&entry_[ahead_]);
            __builtin_prefetch(&ring_[bucket_of(b + 2)]);
        }
    }

    /// One step along the next bucket's list: reads the entry asked for one event ago and asks
    /// for the one it links to. Moving that list's entries into the heap is then a walk through
    /// the cache, not one miss after another (each waits for the previous one's link). A hint
    /// only: an entry moved since leads the walk astray, never the calendar.
    template <class OnAhead>
    void step_ahead(OnAhead& on_ahead) noexcept {
        if (ahead_ >= entry_.size()) return;
        const Entry& e = entry_[ahead_];
        on_ahead(ahead_, e.key);
        ahead_ = e.next;
        if (ahead_ < entry_.size()) __builtin_prefetch(&entry_[ahead_]);
    }

    /// Empties the list at `head`, handing each entry (out of every list) to file(handle).
    template <class File>
    void take_list(handle_type& head, File&& file) {
        handle_type h = head;
        head = none;
        while (h != none) {
            const handle_type next = entry_[h].next;
            entry_[h].slot = none;
            --far_count_;
            file(h);
            h = next;
        }
    }

    /// After every mutation when COLLIDE_VALIDATE is on (see pq::require_invariant).
    void validate() const {
        if constexpr (validate_heaps) {
            require_invariant(check_invariants(), "event calendar blocks / lists");
        }
    }

    [[nodiscard]] std::int64_t earliest_overflow_block() const noexcept {
        std::int64_t b = std::numeric_limits<std::int64_t>::max();
        for (handle_type h = overflow_; h != none; h = entry_[h].next) {
            b = std::min(b, block_of(entry_[h].key.t));
        }
        return b;
    }

    Heap heap_;
    BigVector<Entry> entry_;
    BigVector<handle_type> ring_ = BigVector<handle_type>(2, none);
    std::size_t ring_mask_ = 1;  ///< ring_.size() - 1 (the size is a power of two)
    handle_type overflow_ = none;
    handle_type ahead_ = none;    ///< the next bucket's entry asked for last (see step_ahead)
    bool walk_ahead_ = false;     ///< entries past walk_ahead_bytes: settle() steps ahead
    double inv_width_ = 0.0;      ///< 1 / block width; 0: one block (everything in the heap)
    std::int64_t cur_ = 0;        ///< the current block
    std::size_t far_count_ = 0;   ///< entries in the ring and the overflow list
    std::size_t ring_count_ = 0;  ///< entries in the ring
};

}  // namespace collide::pq

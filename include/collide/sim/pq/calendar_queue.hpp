#pragma once
/// \file
/// An indexed calendar (bucket) queue, for the event-driven engines' one-event-per-disc queue
/// (issue 21 measures it against IndexedDaryHeap). Time is cut into buckets `width` long; bucket
/// k holds the keys whose time falls in [k w, (k + 1) w), and the buckets wrap around a "year" of
/// `buckets` of them (Brown's calendar queue; DynamO's sorted-list queue is a relative). Each
/// handle's key sits in a doubly-linked list through the handles, so change-key and erase are
/// O(1); the earliest key is found by scanning forward from the current bucket for keys of
/// that bucket's year, and kept until a change can beat it. The width is calibrated from the
/// spacing of the earliest keys (a few keys per bucket) and recalibrated every few N pops.
///
/// The order is Less's, strictly: a bucket's index is a monotone function of the time, so keys
/// in different buckets are in time order and keys in one bucket are compared with Less.
/// Key needs a `double t` member; HandleOf reads a key's handle, as in IndexedDaryHeap.

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "collide/error.hpp"

namespace collide::pq {

template <class Key, class Less, class HandleOf>
class IndexedCalendarQueue {
  public:
    using handle_type = std::uint32_t;

    explicit IndexedCalendarQueue(std::size_t capacity = 0, Less less = Less{})
        : less_(std::move(less)) {
        reserve_handles(capacity);
    }

    [[nodiscard]] bool empty() const noexcept { return size_ == 0; }
    [[nodiscard]] std::size_t size() const noexcept { return size_; }

    void reserve_handles(std::size_t capacity) {
        if (capacity > nodes_.size()) nodes_.resize(capacity, Node{Key{}, end, not_in});
    }

    [[nodiscard]] bool contains(handle_type h) const noexcept {
        return h < nodes_.size() && nodes_[h].prev != not_in;
    }

    [[nodiscard]] const Key& key(handle_type h) const {
        if (!contains(h)) throw_runtime_error("calendar queue: key of a handle not in the queue");
        return nodes_[h].key;
    }

    /// The handle of the earliest key. Precondition: !empty(). Amortised O(1) when the width
    /// suits the keys.
    [[nodiscard]] handle_type top() {
        find_top();
        return top_;
    }
    [[nodiscard]] const Key& top_key() {
        find_top();
        return nodes_[top_].key;
    }

    /// Inserts h with key k, or replaces h's key. O(1).
    void push_or_change(handle_type h, const Key& k) {
        if (contains(h)) {
            unlink(h);
        } else {
            ++size_;
        }
        nodes_[h].key = k;
        link(h);
        const std::uint64_t b = bucket_of(k.t);
        if (b < current_) current_ = b;
        if (!top_valid_) return;
        if (h == top_) {
            // Still the earliest only if it moved earlier; otherwise look again when asked.
            top_valid_ = false;
        } else if (less_(k, nodes_[top_].key)) {
            top_ = h;
        }
    }

    void erase(handle_type h) {
        if (!contains(h)) throw_runtime_error("calendar queue: erase of a handle not in the queue");
        unlink(h);
        nodes_[h].prev = not_in;
        --size_;
        if (top_valid_ && h == top_) top_valid_ = false;
    }

    [[nodiscard]] std::size_t bytes() const noexcept {
        return nodes_.capacity() * sizeof(Node) + heads_.capacity() * sizeof(handle_type);
    }

    /// Every contained handle is in the list of its key's bucket, the lists are consistent, and
    /// no key lies before the current bucket. O(capacity + buckets).
    [[nodiscard]] bool check_invariants() const {
        std::size_t listed = 0;
        for (std::size_t b = 0; b < heads_.size(); ++b) {
            handle_type before = head;
            for (handle_type h = heads_[b]; h != end; h = nodes_[h].next) {
                if (h >= nodes_.size() || nodes_[h].prev != before) return false;
                if ((bucket_of(nodes_[h].key.t) & mask_) != b) return false;
                if (bucket_of(nodes_[h].key.t) < current_) return false;
                if (HandleOf{}(nodes_[h].key) != h) return false;
                before = h;
                if (++listed > size_) return false;
            }
        }
        return listed == size_;
    }

  private:
    static constexpr handle_type end = std::numeric_limits<handle_type>::max();
    static constexpr handle_type not_in = end;    ///< prev of a handle not in the queue
    static constexpr handle_type head = end - 1;  ///< prev of the first handle of a list

    struct Node {
        Key key;
        handle_type next;
        handle_type prev;
    };

    [[nodiscard]] std::uint64_t bucket_of(double t) const noexcept {
        const double b = t * inverse_width_;
        constexpr double cap = 4.0e18;
        return b < cap ? static_cast<std::uint64_t>(b) : static_cast<std::uint64_t>(cap);
    }

    void link(handle_type h) {
        if (heads_.empty()) {  // before the first top(): any buckets, calibrated there
            heads_.assign(16, end);
            mask_ = 15;
        }
        Node& n = nodes_[h];
        handle_type& first = heads_[bucket_of(n.key.t) & mask_];
        n.prev = head;
        n.next = first;
        if (first != end) nodes_[first].prev = h;
        first = h;
    }

    void unlink(handle_type h) noexcept {
        Node& n = nodes_[h];
        if (n.prev == head) {
            heads_[bucket_of(n.key.t) & mask_] = n.next;
        } else {
            nodes_[n.prev].next = n.next;
        }
        if (n.next != end) nodes_[n.next].prev = n.prev;
    }

    void find_top() {
        if (top_valid_) return;
        if (uncalibrated_ || ++searches_ > recalibrate_every * std::max<std::size_t>(size_, 64))
            calibrate();
        std::size_t scanned = 0;
        for (;;) {
            handle_type best = end;
            for (handle_type h = heads_[current_ & mask_]; h != end; h = nodes_[h].next) {
                if (bucket_of(nodes_[h].key.t) != current_) continue;  // a later year
                if (best == end || less_(nodes_[h].key, nodes_[best].key)) best = h;
            }
            if (best != end) {
                top_ = best;
                top_valid_ = true;
                return;
            }
            ++current_;
            if (++scanned > heads_.size()) {
                // A whole year without a key: the buckets are too narrow for the keys now.
                calibrate();
                scanned = 0;
            }
        }
    }

    [[nodiscard]] double earliest_time() const noexcept {
        double t = std::numeric_limits<double>::infinity();
        for (const Node& n : nodes_) {
            if (n.prev != not_in) t = std::min(t, n.key.t);
        }
        return t;
    }

    /// Sizes the buckets from the keys present (about `keys_per_bucket` keys per bucket near the
    /// front, as many buckets as keys) and relinks every key. O(capacity).
    void calibrate() {
        searches_ = 0;
        uncalibrated_ = false;
        std::vector<double> sample;
        const std::size_t stride = std::max<std::size_t>(1, nodes_.size() / 1024);
        for (std::size_t h = 0; h < nodes_.size(); h += stride) {
            if (nodes_[h].prev != not_in) sample.push_back(nodes_[h].key.t);
        }
        double width = 1.0;
        if (sample.size() >= 8) {
            std::sort(sample.begin(), sample.end());
            // The spacing of the middle half of the keys: a cluster of keys at one instant (a
            // cascade of touching discs) must not make the buckets vanishingly narrow.
            const std::size_t q1 = sample.size() / 4;
            const std::size_t q3 = 3 * sample.size() / 4;
            const double fraction =
                static_cast<double>(q3 - q1) / static_cast<double>(sample.size());
            const double spacing =
                (sample[q3] - sample[q1]) / (fraction * static_cast<double>(size_));
            if (spacing > 0.0 && std::isfinite(spacing)) width = keys_per_bucket * spacing;
        }
        inverse_width_ = 1.0 / width;
        const std::size_t buckets = std::bit_ceil(std::max<std::size_t>(size_, 16));
        mask_ = buckets - 1;
        heads_.assign(buckets, end);
        for (handle_type h = 0; h < nodes_.size(); ++h) {
            if (nodes_[h].prev != not_in) link(h);
        }
        current_ = size_ > 0 ? bucket_of(earliest_time()) : 0;
        top_valid_ = false;
    }

    static constexpr double keys_per_bucket = 2.0;
    static constexpr std::size_t recalibrate_every = 2;  ///< pops per key between calibrations

    std::vector<Node> nodes_;
    std::vector<handle_type> heads_;
    std::uint64_t mask_ = 0;
    double inverse_width_ = 1.0;
    std::uint64_t current_ = 0;  ///< no key lies in an earlier bucket
    std::size_t size_ = 0;
    std::size_t searches_ = 0;
    handle_type top_ = end;
    bool top_valid_ = false;
    bool uncalibrated_ = true;  ///< the keys pushed before the first top() set the width
    Less less_;
};

}  // namespace collide::pq

#pragma once
/// \file
/// The fast engine's event queue: an event calendar (CalendarQueue, which also runs as one
/// indexed heap) or a tournament tree (TournamentTree), whichever the engine chose for its scene
/// (BasicFastEngine::tune_calendar). One pending event per handle in either; both pop in the
/// order of the same Less, so the choice changes speed and memory, never the events.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "collide/sim/pq/calendar_queue.hpp"
#include "collide/sim/pq/tournament_tree.hpp"

namespace collide::pq {

template <class Key, class Less, class HandleOf>
class CalendarOrTree {
  public:
    using handle_type = std::uint32_t;
    using Calendar = CalendarQueue<Key, Less, HandleOf>;
    using Tree = TournamentTree<Key, Less, HandleOf>;

    explicit CalendarOrTree(std::size_t capacity = 0, Less less = Less{})
        : calendar_(capacity, less), tree_(0, less), less_(less), capacity_(capacity) {}

    void reserve_handles(std::size_t capacity) {
        capacity_ = std::max(capacity_, capacity);
        if (tree_on_) {
            tree_.reserve_handles(capacity);
        } else {
            calendar_.reserve_handles(capacity);
        }
    }

    /// The calendar, tuned as CalendarQueue::tune says (moving the tree's entries into it).
    void tune(double width, std::size_t buckets, double now) {
        if (tree_on_) {
            calendar_.reserve_handles(capacity_);
            move_entries(tree_, calendar_);
            tree_.release();
            tree_on_ = false;
        }
        calendar_.tune(width, buckets, now);
    }

    /// The tournament tree (moving the calendar's entries into it and freeing its lists).
    void use_tree() {
        if (tree_on_) return;
        tree_.reserve_handles(capacity_);
        move_entries(calendar_, tree_);
        calendar_ = Calendar(0, less_);  // frees its heap's keys and position map
        tree_on_ = true;
    }

    [[nodiscard]] bool tree() const noexcept { return tree_on_; }

    [[nodiscard]] std::size_t size() const noexcept {
        return tree_on_ ? tree_.size() : calendar_.size();
    }
    [[nodiscard]] bool contains(handle_type h) const noexcept {
        return tree_on_ ? tree_.contains(h) : calendar_.contains(h);
    }
    [[nodiscard]] const Key& key(handle_type h) const {
        return tree_on_ ? tree_.key(h) : calendar_.key(h);
    }
    bool settle() { return tree_on_ ? tree_.settle() : calendar_.settle(); }
    [[nodiscard]] handle_type top() const { return tree_on_ ? tree_.top() : calendar_.top(); }
    [[nodiscard]] const Key& top_key() const {
        return tree_on_ ? tree_.top_key() : calendar_.top_key();
    }

    [[gnu::always_inline]] void push_or_change(handle_type h, const Key& k) {
        if (tree_on_) {
            tree_.push_or_change(h, k);
        } else {
            calendar_.push_or_change(h, k);
        }
    }
    void erase(handle_type h) {
        if (tree_on_) {
            tree_.erase(h);
        } else {
            calendar_.erase(h);
        }
    }

    template <class Visit>
    void for_each(Visit&& visit) const {
        if (tree_on_) {
            tree_.for_each(visit);
        } else {
            calendar_.for_each(visit);
        }
    }

    /// The calendar's heap (empty while the tree is on; watched engines keep the calendar).
    [[nodiscard]] const typename Calendar::Heap& near() const noexcept { return calendar_.near(); }

    [[nodiscard]] std::size_t bytes() const noexcept { return calendar_.bytes() + tree_.bytes(); }

    [[nodiscard]] bool check_invariants() const {
        return calendar_.check_invariants() && tree_.check_invariants() &&
               (tree_on_ ? calendar_.empty() : tree_.empty());
    }

  private:
    template <class From, class To>
    static void move_entries(From& from, To& to) {
        std::vector<Key> all;
        all.reserve(from.size());
        from.for_each([&](handle_type, const Key& k) { all.push_back(k); });
        for (const Key& k : all) {
            from.erase(HandleOf{}(k));
            to.push_or_change(HandleOf{}(k), k);
        }
    }

    Calendar calendar_;
    Tree tree_;
    Less less_;
    std::size_t capacity_ = 0;
    bool tree_on_ = false;
};

}  // namespace collide::pq

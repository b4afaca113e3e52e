#pragma once
/// \file
/// The pseudocode of `collide heap --code`: for each operation of a heap lesson the lines a class
/// reads beside the tree (insert and swim, remove-the-maximum and sink, increase-key, both passes
/// of heapsort), in the project's own words, and which line each recorded step carries out
/// (collide/sim/pq/heap_record.hpp: steps by kind). HeapProgram (heap_program.hpp) puts them into
/// its frames; this header lets tests hold the mapping against the record. Pure: no drawing.

#include <cstddef>
#include <optional>
#include <vector>

#include "collide/sim/pq/heap_record.hpp"
#include "collide/view/code.hpp"

namespace collide::show {

/// Whether a lesson can show its code: one panel, and that panel a heap (binary, d-ary or
/// indexed). The arrays' code is not written, and several panels would each need their own
/// highlight.
[[nodiscard]] bool heap_code_fits(const pq::HeapRecord& record) noexcept;

/// The listing of an operation of kind `op` for a queue of `orientation`: the operation's own
/// lines, then the helper it calls (swim or sink). Max-oriented words ("the larger child",
/// "a[p] >= a[k]") turn around for a min-queue; increase-key calls swim in a max-queue and sink
/// in a min-queue (a larger key moves away from the top there).
[[nodiscard]] std::vector<view::CodeLineView> heap_code(pq::HeapOp::Kind op,
                                                        pq::Orientation orientation);

/// The line of heap_code(op, orientation) that step `s` of `done` carries out, as an index into
/// that listing; none for a step no line stands for. `panel` gives the heap's arity (which keys
/// are siblings). Precondition: s < done.steps.size().
[[nodiscard]] std::optional<std::size_t> heap_code_line(const pq::HeapPanel& panel,
                                                        pq::HeapOp::Kind op,
                                                        pq::Orientation orientation,
                                                        const pq::PanelOp& done, std::size_t s);

}  // namespace collide::show

#pragma once
/// \file
/// Frames of a priority-queue lesson (`collide heap`): each panel a queue drawn as its tree
/// (binary or d-ary heap: nodes with their keys, edges) above its array (slots with their
/// indices), or as the array alone (unordered and ordered arrays), with highlights for the keys
/// being compared, keys sliding along their edge and in the array during an exchange, a caption
/// and counters; the indexed heap's map from key to index beside its tree; a strip of the
/// operations on top with the current one marked. Rendered offscreen with OpenGL like the
/// collision video (same context backends, shaders and text blending), to RGBA images.
///
/// The module sees plain values only (no simulation types): the app fills a HeapFrameView from
/// the animation model (collide/sim/pq/heap_lesson.hpp) for every frame.
///
///     HeapViewConfig config; config.width = 1280; config.height = 720;
///     HeapRenderer renderer(config);
///     HeapFrameView frame; frame.tokens = {"P", "Q", "*"}; frame.current_token = 1;
///     frame.panels.push_back(panel);   // slots, marks, an exchange under way, caption, counters
///     Image image = renderer.render(frame);

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "collide/image.hpp"
#include "collide/render/context.hpp"
#include "collide/render/renderer.hpp"

namespace collide::render {

/// How one key is highlighted.
enum class SlotMark : std::uint8_t {
    plain,
    compared,  ///< one of the two keys being compared
    moving,    ///< one of the two keys being exchanged (or shifted)
    inserted,  ///< a key that just appeared
    changed,   ///< a key just changed (increase-key)
    best,      ///< the unordered array's scan: the max (min) so far
    leaving,   ///< the key being removed (fades out over HeapPanelView::fade)
    sinking,   ///< heapsort's construction: the root of the next sink
};

/// One slot of a queue's array (and the node of the tree that holds the same key).
struct HeapSlotView {
    std::string key;
    SlotMark mark = SlotMark::plain;
};

/// Two slots whose keys are on their way to each other's place: at t = 0 each is in its own
/// slot, at t = 1 in the other's (the app eases t).
struct HeapSwapView {
    std::size_t a = 0;
    std::size_t b = 0;
    float t = 0.0F;
};

/// One row of the indexed heap's map: a key and the array index it sits at.
struct HeapMapRow {
    std::string key;
    std::string index;     ///< as shown, e.g. "3"
    bool updated = false;  ///< its index changes in the exchange under way
};

/// One queue.
struct HeapPanelView {
    std::string title;                  ///< "binary heap (max)"
    std::vector<std::string> counters;  ///< e.g. {"compares 12", "exchanges 5"}
    std::string caption;                ///< what happens, wrapped to the panel's width
    bool tree = true;                   ///< a heap: tree above the array; false: array only
    unsigned arity = 2;                 ///< children per node (tree only), >= 2
    /// Slots the layout holds (the most keys the queue ever holds in this video), so that nodes
    /// keep their places for the whole video. >= slots.size().
    std::size_t capacity = 0;
    std::vector<HeapSlotView> slots;  ///< the array, slot 0 first
    /// Slots [heap_size, slots.size()) are heapsort's sorted part: set apart in the array, not
    /// in the tree. heap_size >= slots.size() means none.
    std::size_t heap_size = SIZE_MAX;
    std::optional<HeapSwapView> swap;  ///< an exchange under way
    float fade = 1.0F;                 ///< opacity of inserted (fading in) / leaving keys, [0, 1]
    int index_base = 1;                ///< the index shown under slot 0
    bool show_map = false;             ///< indexed heap: draw `map` beside the tree
    std::vector<HeapMapRow> map;
};

/// One frame.
struct HeapFrameView {
    std::vector<std::string> tokens;  ///< the operations, shown in a strip on top
    /// The operation under way (marked); tokens before it are done. Unset: none yet.
    std::optional<std::size_t> current_token;
    std::vector<HeapPanelView> panels;  ///< 1 to max_heap_panels, left to right, top to bottom
};

/// Everything fixed for a whole video.
struct HeapViewConfig {
    int width = 1280;  ///< frame width in pixels, min_frame_side..max_frame_side (renderer.hpp)
    int height = 720;  ///< frame height in pixels, as width
    /// The widest key of the video: node and slot text is sized so that it fits.
    std::string widest_key = "W";
    std::string font_path = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    /// dark (screens) or light (projectors, print): the collision video's themes.
    Theme theme = Theme::dark;

    /// Throws Error(input) naming the first bad field.
    void validate() const;
};

/// Most panels in one frame.
inline constexpr std::size_t max_heap_panels = 6;

/// The most keys a queue may hold at once when `panels` queues share the frame (side by side)
/// and still be drawn legibly: 36 / panels (36 for one panel, 12 for three, 7 for five: the
/// lecture's trace holds 7), which keeps array slots over ~21 px wide and keys over ~13 px tall
/// at 854x480 (-q l), half as much again at 720p.
[[nodiscard]] std::size_t max_legible_keys(std::size_t panels) noexcept;

/// Draws lesson frames with a GL context it owns. Not thread-safe; one per thread.
class HeapRenderer {
  public:
    /// Creates the context and GL resources. Throws Error: input for a bad config, runtime when
    /// the context, shaders or font cannot be set up.
    explicit HeapRenderer(const HeapViewConfig& config, Backend backend = Backend::automatic,
                          const NoticeSink& notice = {});
    ~HeapRenderer();
    HeapRenderer(HeapRenderer&&) noexcept;
    HeapRenderer& operator=(HeapRenderer&&) noexcept;
    HeapRenderer(const HeapRenderer&) = delete;
    HeapRenderer& operator=(const HeapRenderer&) = delete;

    /// Draws one frame, width x height RGBA8, rows top-down, into `out` (resized as needed).
    /// Throws Error(input) for no panels, more than max_heap_panels, more slots than a panel's
    /// capacity or an exchange of slots that do not exist.
    void render(const HeapFrameView& frame, Image& out);
    [[nodiscard]] Image render(const HeapFrameView& frame);

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace collide::render

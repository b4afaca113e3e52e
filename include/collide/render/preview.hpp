#pragma once
/// \file
/// A visible window showing frames as they are produced (`--preview`): a live view while the
/// video encodes. Needs a display; without one, open_preview returns null after one notice.

#include <memory>

#include "collide/image.hpp"
#include "collide/render/context.hpp"

namespace collide::render {

/// A GLFW window with its own GL context that displays images. Move-only (held by unique_ptr).
class PreviewWindow {
  public:
    PreviewWindow(const PreviewWindow&) = delete;
    PreviewWindow& operator=(const PreviewWindow&) = delete;
    virtual ~PreviewWindow() = default;

    /// Shows `image` (scaled to the window) and processes window events. Returns false once the
    /// user has closed the window (the caller keeps encoding; further calls do nothing).
    /// Throws collide::Error (runtime) on GL failure.
    virtual bool show(const Image& image) = 0;

  protected:
    PreviewWindow() = default;
};

/// Opens a preview window of `width` x `height` pixels titled `title`, hidden until the first
/// show(). Returns null (after one notice) when no display is available; never throws for that
/// reason. While it is open, render with Backend::glfw: OSMesa and the window's GLX driver share
/// Mesa's per-thread current context but each keeps its own record of it, so interleaving them
/// draws with the wrong context (docs/renderer.md, "Preview").
[[nodiscard]] std::unique_ptr<PreviewWindow> open_preview(int width, int height, const char* title,
                                                          const NoticeSink& notice = {});

}  // namespace collide::render

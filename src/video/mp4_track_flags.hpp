#pragma once
// The MP4 muxer's one decision we undo: which subtitle track a player shows unasked.

#include <filesystem>

namespace collide::video {

/// Clears the "enabled" flag (ISO/IEC 14496-12 tkhd flag 0x000001) of every subtitle track
/// (handler 'sbtl') in the MP4 file at `path`, so that players (and ffprobe's
/// disposition "default") treat the track as off until the viewer picks it. FFmpeg's muxer
/// enables the first track of each kind whatever the stream's disposition; a video whose
/// captions are already in the picture must not show them twice. Rewrites the flag bytes in
/// place, nothing else. Throws Error(runtime) when the file cannot be read or written, or holds
/// no 'moov' box.
void disable_subtitle_tracks(const std::filesystem::path& path);

}  // namespace collide::video

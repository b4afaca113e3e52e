#pragma once
/// \file
/// Subtitles as the encoder writes them: cues (plain text with times, collide/cue.hpp) tagged
/// with a language, as an MP4 subtitle track (VideoOptions::subtitles) or as a WebVTT or SubRip
/// file beside the video. Nothing here knows what the words mean or where they came from.

#include <filesystem>
#include <string>
#include <string_view>

#include "collide/cue.hpp"

namespace collide::video {

/// The ISO 639-2/T code (what MP4 stores: "pol", "deu", "und") for `tag`: a two-letter ISO 639-1
/// code ("pl"), a three-letter ISO 639-2 code in either form ("ger" or "deu"), any case.
/// Throws Error(input) naming `field` for anything else ("--lang: 'xx' is not an ISO 639
/// language code ...").
[[nodiscard]] std::string subtitle_language(std::string_view tag, std::string_view field = "lang");

/// The sidecar formats: WebVTT (browsers' <track>) and SubRip (.srt: most players and editors).
enum class SubtitleFormat { webvtt, srt };

/// The format a sidecar's name asks for: ".vtt" or ".srt" (any case). Throws Error(input) naming
/// `field` for another extension.
[[nodiscard]] SubtitleFormat subtitle_format_of(const std::filesystem::path& path,
                                                std::string_view field = "subtitles_file");

/// A cue's text as every subtitle output carries it (WebVTT, SubRip, the MP4 track): its lines,
/// split at '\n' and at a lone '\r', without blank ones (an empty line ends a cue in a file),
/// control characters (C0 but tab, DEL, C1) dropped, tabs as spaces, and every "-->" (the arrow
/// of a cue timing line) shortened to "->" until none is left ("--->" too), so that no text can
/// ever read as the start of a cue of its own.
[[nodiscard]] std::string plain_cue_text(std::string_view text);

/// The cues as a WebVTT file ("WEBVTT", then "HH:MM:SS.mmm --> HH:MM:SS.mmm" blocks; '&', '<'
/// and '>' escaped; the text as plain_cue_text gives it).
[[nodiscard]] std::string webvtt_text(const Cues& cues);
/// The cues as a SubRip file (numbered blocks, "HH:MM:SS,mmm --> HH:MM:SS,mmm", CRLF-free UTF-8,
/// the text as plain_cue_text gives it).
[[nodiscard]] std::string srt_text(const Cues& cues);
/// Chapters as a WebVTT chapters file (what a <track kind="chapters"> reads): one cue per
/// chapter, its title as the text, in the same form as webvtt_text.
[[nodiscard]] std::string webvtt_chapters_text(const Chapters& chapters);
/// One of the two, by `format`.
[[nodiscard]] std::string subtitle_file_text(const Cues& cues, SubtitleFormat format);

}  // namespace collide::video

// The slide player: one HTML page with inline CSS and JavaScript that plays the lesson video and
// stops at each chapter's end. Everything it needs is in the page or beside it (file://).
#include "collide/show/slide_player.hpp"

#include <algorithm>
#include <cstdio>
#include <string_view>
#include <utility>
#include <vector>

#include "collide/show/chapters.hpp"

namespace collide::show {
namespace {

/// Text for HTML element content or a quoted attribute.
std::string html_escaped(std::string_view text) {
    std::string out;
    for (const char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

/// A JavaScript string literal that is also safe inside <script> ("</script>" and "<!--" cannot
/// occur: '<' is escaped), and for the line separators JSON allows but older JavaScript not.
std::string js_string(std::string_view text) {
    std::string out = "\"";
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += static_cast<char>(c);
        } else if (c < 0x20 || c == '<' || c == '>' || c == '&') {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
            out += escaped;
        } else if (c == 0xE2 && i + 2 < text.size() &&
                   static_cast<unsigned char>(text[i + 1]) == 0x80 &&
                   (static_cast<unsigned char>(text[i + 2]) == 0xA8 ||
                    static_cast<unsigned char>(text[i + 2]) == 0xA9)) {
            out += static_cast<unsigned char>(text[i + 2]) == 0xA8 ? "\\u2028" : "\\u2029";
            i += 2;
        } else {
            out += static_cast<char>(c);
        }
    }
    return out + "\"";
}

std::string seconds(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

/// [{start, end, text}, ...] as a JavaScript array (chapters also with `still`).
std::string js_array(const Cues& cues) {
    std::string out = "[";
    for (const Cue& cue : cues) {
        if (out.size() > 1) out += ",\n  ";
        out += "{start: " + seconds(cue.start) + ", end: " + seconds(cue.end) +
               ", text: " + js_string(cue.text) + "}";
    }
    return out + "]";
}

std::string js_array(const Chapters& chapters) {
    std::string out = "[";
    for (const Chapter& chapter : chapters) {
        if (out.size() > 1) out += ",\n  ";
        out += "{start: " + seconds(chapter.start) + ", end: " + seconds(chapter.end) +
               ", still: " + seconds(chapter.still) + ", text: " + js_string(chapter.title) + "}";
    }
    return out + "]";
}

/// The template with each @NAME@ replaced by its value, in one pass (so that a value holding
/// "@NAME@" stays as it is).
std::string filled(std::string_view text,
                   const std::vector<std::pair<std::string_view, std::string>>& values) {
    std::string out;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t open = text.find('@', at);
        const std::size_t close = open == std::string_view::npos ? open : text.find('@', open + 1);
        if (close == std::string_view::npos) break;
        out += text.substr(at, open - at);
        const std::string_view name = text.substr(open + 1, close - open - 1);
        bool known = false;
        for (const auto& [key, value] : values) {
            if (key != name) continue;
            out += value;
            known = true;
        }
        if (!known) out += text.substr(open, close - open + 1);
        at = close + 1;
    }
    out += text.substr(std::min(at, text.size()));
    return out;
}

constexpr std::string_view page_template = R"HTML(<!DOCTYPE html>
<html lang="@LANG@">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>@TITLE@</title>
<style>
html, body { margin: 0; height: 100%; background: #000; color: #ddd;
  font: 16px/1.3 "DejaVu Sans", sans-serif; overflow: hidden; }
#stage { position: fixed; left: 0; right: 0; top: 0; bottom: 2.6em; }
video { width: 100%; height: 100%; object-fit: contain; background: #000; cursor: pointer; }
#bar { position: fixed; left: 0; right: 0; bottom: 0; height: 2.6em; display: flex;
  align-items: center; gap: 0.6em; padding: 0 0.8em; background: #161616; }
#bar button { font: inherit; color: #eee; background: #2a2a2a; border: 1px solid #444;
  border-radius: 4px; padding: 0.15em 0.7em; cursor: pointer; }
#bar button:hover { background: #3a3a3a; }
#bar button[aria-pressed="false"] { color: #888; }
#where { flex: 1; white-space: nowrap; overflow: hidden; text-overflow: ellipsis; }
#keys { color: #888; font-size: 0.85em; white-space: nowrap; }
:fullscreen #stage { bottom: 0; }
:fullscreen #bar { display: none; }
</style>
</head>
<body>
<div id="stage">
<video id="video" src="@VIDEO@" preload="auto" muted playsinline>@TRACK@</video>
</div>
<div id="bar">
<button id="back" title="Back a chapter (left arrow)">&#9664;</button>
<button id="next" title="Go on (right arrow, space or a click)">&#9654;</button>
<span id="where"></span>
<span id="keys">&#8594; / space: go on &#183; &#8592;: back &#183; F: full screen<span id="subs-key"> &#183; S: subtitles</span></span>
<button id="subs" title="Subtitles on and off (S)" aria-pressed="true">Subtitles</button>
<button id="full" title="Full screen (F)">Full screen</button>
</div>
<pre id="test-log" hidden></pre>
<script>
"use strict";
// Where the player stops: each chapter's still, its last frame (a title card: before it fades).
const chapters = @CHAPTERS@;
// The subtitles again, for browsers that refuse to read the .vtt file from file://.
const cues = @CUES@;
const frame = 1 / @FPS@;
// The captions are drawn into the video: the track stays hidden (no caption drawn twice) and
// there is nothing to switch on.
const captionsInPicture = @IN_PICTURE@;
const video = document.getElementById("video");
const where = document.getElementById("where");
let current = 0;       // the chapter on screen
let state = "ready";   // ready: at its start; playing; done: stopped at its end

// The middle of the still's frame, so that the browser shows that frame and no neighbour.
function stopTime(i) { return chapters[i].still + frame / 2; }

function show() {
  const last = current + 1 === chapters.length && state === "done";
  where.textContent = (current + 1) + " / " + chapters.length + ": " + chapters[current].text +
    (last ? " (the end)" : "");
}

function finish() {
  video.pause();
  video.currentTime = stopTime(current);
  state = "done";
  show();
}

// Stops at the chapter's still: checked every animation frame while playing (timeupdate alone
// comes only every quarter second or so).
function check() {
  if (state === "playing" && (video.currentTime >= stopTime(current) || video.ended)) finish();
}
function watch() {
  check();
  if (state === "playing") requestAnimationFrame(watch);
}

function play() {
  state = "playing";
  show();
  const started = video.play();
  if (started) started.catch(function (error) { state = "ready"; show(); note("error " + error); });
  requestAnimationFrame(watch);
}

// Right arrow, space, a click: play the chapter, skip to its end, or play the next one.
function goOn() {
  if (state === "ready") { play(); return; }
  if (state === "playing") { finish(); return; }
  if (current + 1 < chapters.length) { current += 1; play(); }
}

// Left arrow: back to where the previous chapter stopped (the first one's start).
function goBack() {
  video.pause();
  if (current === 0) {
    current = 0;
    state = "ready";
    video.currentTime = chapters[0].start;
  } else {
    current -= 1;
    state = "done";
    video.currentTime = stopTime(current);
  }
  show();
}

function subtitleTrack() {
  const tracks = video.textTracks;
  for (let i = tracks.length - 1; i >= 0; --i) if (tracks[i].kind === "subtitles") return tracks[i];
  return null;
}

function toggleSubtitles() {
  const track = subtitleTrack();
  if (!track || captionsInPicture) return;
  track.mode = track.mode === "showing" ? "hidden" : "showing";
  document.getElementById("subs").setAttribute("aria-pressed", String(track.mode === "showing"));
}

function toggleFullScreen() {
  if (document.fullscreenElement) document.exitFullscreen();
  else document.documentElement.requestFullscreen().catch(function () {});
}

// The <track> file cannot be read (Chrome and Firefox treat every file:// page as its own
// origin): the same cues from the page instead.
function subtitlesFromPage() {
  const element = video.querySelector("track");
  if (element) element.remove();
  if (cues.length === 0 || typeof VTTCue === "undefined") return;
  const track = video.addTextTrack("subtitles", "Subtitles", "@LANG@");
  for (const cue of cues) track.addCue(new VTTCue(cue.start, cue.end, cue.text));
  track.mode = captionsInPicture ? "hidden" : "showing";
}
const trackElement = video.querySelector("track");
if (trackElement) trackElement.addEventListener("error", subtitlesFromPage);
else subtitlesFromPage();
if (captionsInPicture) {
  // Hidden, not disabled: the cues still load (a search, a screen reader), nothing is drawn.
  const track = subtitleTrack();
  if (track) track.mode = "hidden";
  document.getElementById("subs").hidden = true;
  document.getElementById("subs-key").hidden = true;
}

document.addEventListener("keydown", function (event) {
  if (event.altKey || event.ctrlKey || event.metaKey) return;
  const key = event.key;
  if (key === "ArrowRight" || key === " " || key === "PageDown") goOn();
  else if (key === "ArrowLeft" || key === "PageUp") goBack();
  else if (key === "f" || key === "F") toggleFullScreen();
  else if (key === "s" || key === "S") toggleSubtitles();
  else return;
  event.preventDefault();
});
video.addEventListener("click", goOn);
video.addEventListener("timeupdate", check);
video.addEventListener("ended", check);
// A clicked button gives its focus back, so that space goes on rather than clicking it again.
function button(id, action) {
  const element = document.getElementById(id);
  element.addEventListener("click", function () { action(); element.blur(); });
}
button("next", goOn);
button("back", goBack);
button("subs", toggleSubtitles);
button("full", toggleFullScreen);
show();

// ?test: play two chapters by pressing the keys a lecturer would, and log what happened
// (?test=N: N chapters, to reach a later one, a question and then its answer).
const log = document.getElementById("test-log");
function note(line) { log.textContent += line + "\n"; }
// How many text tracks the browser draws over the video now.
function showing() {
  let n = 0;
  for (let i = 0; i < video.textTracks.length; ++i) if (video.textTracks[i].mode === "showing") ++n;
  return n;
}
function press(key) { document.dispatchEvent(new KeyboardEvent("keydown", {key: key, bubbles: true})); }
function until(test) {
  return new Promise(function (resolve) {
    (function poll() { if (test()) resolve(); else setTimeout(poll, 10); })();
  });
}
function pause(ms) { return new Promise(function (resolve) { setTimeout(resolve, ms); }); }
async function selfTest() {
  await until(function () { return video.readyState >= 1; });
  note("chapters " + chapters.length);
  await pause(100);  // the <track> file loads, or fails and the page's cues take its place
  const track = subtitleTrack();
  note("subtitles " + (track && track.cues ? track.cues.length : 0));
  note("showing " + showing());
  const asked = /[?&]test=([0-9]+)/.exec(location.search);
  const presses = Math.min(asked ? Number(asked[1]) : 2, chapters.length);
  for (let n = 0; n < presses; ++n) {
    press("ArrowRight");
    await until(function () { return state === "done"; });
    await pause(300);  // still stopped a moment later
    note("stop " + current + " " + video.currentTime.toFixed(3) + (video.paused ? " paused" : " playing"));
    note("title " + current + " " + chapters[current].text);
    note("showing " + showing());
  }
  press("ArrowLeft");
  note("back " + current + " " + video.currentTime.toFixed(3));
  note("end");
}
if (/[?&]test(=|&|$)/.test(location.search)) selfTest();
</script>
</body>
</html>
)HTML";

}  // namespace

std::string slide_page_html(const SlidePage& page) {
    std::string track;
    if (!page.subtitles.empty()) {
        track = "<track kind=\"subtitles\" src=\"" + html_escaped(page.subtitles) +
                "\" srclang=\"" + html_escaped(page.language) + "\" label=\"Subtitles\"" +
                (page.cues_in_picture ? ">" : " default>");
    }
    return filled(page_template,
                  {{"TITLE", html_escaped(page.title.empty() ? "collide" : one_line(page.title))},
                   {"LANG", html_escaped(page.language.empty() ? "und" : page.language)},
                   {"VIDEO", html_escaped(page.video)},
                   {"TRACK", track},
                   {"CHAPTERS", js_array(page.chapters)},
                   {"CUES", js_array(page.cues)},
                   {"FPS", std::to_string(page.fps > 0 ? page.fps : 30)},
                   {"IN_PICTURE", page.cues_in_picture ? "true" : "false"}});
}

}  // namespace collide::show

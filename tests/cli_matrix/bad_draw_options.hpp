#pragma once
// The bad option sets of `collide render`, `collide thumbnail` and `collide heap` that the option
// matrix refuses (test_option_matrix.cpp), shared with the test that `collide` refuses them
// itself, with collide-draw's words, without starting it (tests/app/test_draw_checks_cli.cpp).

#include <string>
#include <vector>

namespace collide::test {

/// One bad option set and what its refusal must say.
struct Bad {
    std::string args;         ///< options after the subcommand (-o is added for render/thumbnail)
    std::string option;       ///< what the message must name first
    std::string detail = "";  ///< more the message must say (what was expected, the value), if any
    /// CLI11's own usage errors ("Could not convert: --fps = abc", "not expected: 1 --at") name
    /// the option, but not first.
    bool usage = false;
};

// Render and thumbnail refuse before creating any output: a path that must never appear.
inline const std::string never = " -o /nonexistent-dir-collide/never";

/// render: numbers, sizes and names out of range or unknown, options that need others.
inline std::vector<Bad> bad_render_options() {
    std::vector<Bad> cases;
    for (const char* v : {"0", "-1", "241", "1e3", "30.5", "99999999999", "abc", "0x10"})
        cases.push_back({std::string("gas --fps ") + v + never + ".mp4", "--fps"});
    for (const char* v : {"0", "-1", "nan", "inf", "1e300", "3601", "-0"})
        cases.push_back({std::string("gas --duration ") + v + never + ".mp4", "--duration"});
    for (const char* v : {"0", "-1", "nan", "inf", "-inf", "1e300", "1e308", "1e-400"})
        cases.push_back({std::string("gas --speed ") + v + never + ".mp4", "--speed"});
    for (const char* v : {"0", "-1", "nan", "inf", "1e-300", "5e-324", "1e-9"})
        cases.push_back({std::string("gas --dt ") + v + never + ".mp4", "--dt"});
    cases.push_back({"gas --dt 1e-300 --no-limits" + never + ".mp4", "--dt"});
    cases.push_back({"gas --speed 1e308 --no-limits" + never + ".mp4", "--speed"});
    for (const char* v : {"0x0", "64", "99999x64", "-64x64", "64x1e3", "64x99999999999", "x"})
        cases.push_back({std::string("gas --size ") + v + never + ".mp4", "--size"});
    for (const char* v : {"-1", "18446744073709551616", "1e23", "0x10", "1.5", "-0"})
        cases.push_back({std::string("gas --seed ") + v + never + ".mp4", "--seed"});
    cases.push_back({"gas -q z" + never + ".mp4", "-q"});
    cases.push_back({"gas --mode sideways" + never + ".mp4", "--mode"});
    cases.push_back(
        {"gas --engine warp" + never + ".mp4", "--engine", "(fast or classic), got 'warp'"});
    cases.push_back({"gas --engine time" + never + ".mp4", "--engine", "event-driven"});
    for (const char* v : {"dary:0", "dary:-1", "dary:99999999999999999999", "indexed:1e3", "heap"})
        cases.push_back({std::string("gas --pq ") + v + never + ".mp4", "--pq", "expected"});
    cases.push_back(
        {"gas --pq indexed:5 --engine classic" + never + ".mp4", "--pq", "D = 2, 3, 4 or 8"});
    cases.push_back({"gas --td-detect magic" + never + ".mp4", "--td-detect",
                     "expected all-pairs or grid, got 'magic'"});
    cases.push_back({"gas --gl vulkan" + never + ".mp4", "--gl", "vulkan"});
    cases.push_back({"gas-3d --camera spin" + never + ".mp4", "--camera", "fixed or orbit"});
    cases.push_back(
        {"gas-3d --projection fisheye" + never + ".mp4", "--projection", "ortho or perspective"});
    for (const char* v : {"0", "-1", "nan"})
        cases.push_back({std::string("gas-3d --slab ") + v + never + ".mp4", "--slab"});
    cases.push_back({"gas --overlays loud" + never + ".mp4", "--overlays", "loud"});
    cases.push_back({"gas --theme sepia" + never + ".mp4", "--theme", "sepia"});
    cases.push_back({"gas --layout-json ''" + never + ".mp4", "--layout-json"});
    cases.push_back({"gas" + never + ".avi", "-o", "got '/nonexistent-dir-collide/never.avi'"});
    cases.push_back({"gas" + never + ".png", "-o", "single image"});
    cases.push_back({"gas --color plaid" + never + ".mp4", "--color"});
    cases.push_back({"gas --format avi" + never + ".mp4", "--format"});
    cases.push_back({"gas --at 1" + never + ".mp4", "--at", "", true});
    cases.push_back({"gas --last-frame --format gif" + never + ".png", "--format", "png"});
    cases.push_back({"gas --last-frame" + never + ".gif", "-o", "a .png path"});
    cases.push_back({"gas --progress loud" + never + ".mp4", "--progress"});
    for (const char* v : {"0", "21", "-1", "2.5", "1e3", "x", "99999999999999999999"})
        cases.push_back({std::string("gas --queue ") + v + never + ".mp4", "--queue"});
    cases.push_back({"gas --queue --mode time" + never + ".mp4", "--queue"});
    cases.push_back({"gas --queue 3 --mode time --engine classic" + never + ".mp4", "--queue"});
    cases.push_back({"gas --queue --overlays none" + never + ".mp4", "--queue"});
    cases.push_back({"gas --queue --overlays full" + never + ".mp4", "--queue"});
    // --code: the loop beside the queue, at the lesson level, in a frame of 854 px or more.
    cases.push_back({"gas --code" + never + ".mp4", "--code", "add --queue"});
    cases.push_back({"gas --queue --code --overlays none" + never + ".mp4", "--code", "lesson"});
    cases.push_back({"gas --queue --code --overlays full" + never + ".mp4", "--code", "lesson"});
    cases.push_back({"gas --queue --code --size 640x360" + never + ".mp4", "--code", "854 pixels"});
    cases.push_back({"gas-3d --queue --code" + never + ".mp4", "--code", "3D"});
    for (const char* v : {"0", "0.5", "-2", "nan", "inf", "1e9", "abc"})
        cases.push_back({std::string("gas --slow-motion ") + v + never + ".mp4", "--slow-motion",
                         "", v == std::string("abc")});
    return cases;
}

/// thumbnail: --at at every extreme, and the options it shares with render.
inline std::vector<Bad> bad_thumbnail_options() {
    std::vector<Bad> cases;
    for (const char* v : {"-1", "nan", "inf", "1e18", "1e15", "1e300", "1e308", "1e6"})
        cases.push_back({std::string("gas --at ") + v + never + ".png", "--at"});
    cases.push_back({"gas --at 1 --speed 1e-300" + never + ".png", "--at"});
    cases.push_back({"gas --at 1e18 --no-limits" + never + ".png", "--at"});
    cases.push_back({"gas --at 1 --fps 0" + never + ".png", "--fps"});
    cases.push_back({"gas --at 1 --seed -1" + never + ".png", "--seed"});
    cases.push_back({"gas" + never + ".gif", "-o", "a .png path"});
    cases.push_back({"gas --engine time" + never + ".png", "--engine", "fast or classic"});
    cases.push_back({"gas --at 1 --queue 0" + never + ".png", "--queue"});
    cases.push_back({"gas --at 1 --queue --mode time" + never + ".png", "--queue"});
    return cases;
}

/// heap: its numbers and names, its frame, its destination and --code.
inline std::vector<Bad> bad_heap_options() {
    std::vector<Bad> cases;
    for (const char* v : {"0", "-1", "nan", "inf", "61"})
        cases.push_back({std::string("--ops P --pace ") + v + never + ".mp4", "--pace"});
    cases.push_back({"--ops P --index-base 2" + never + ".mp4", "--index-base", "0 or 1"});
    for (const char* v : {"0", "241", "abc"})
        cases.push_back({std::string("--ops P --fps ") + v + never + ".mp4", "--fps", "",
                         v == std::string("abc")});
    cases.push_back({"--ops P --impl heap" + never + ".mp4", "--impl", "got 'heap'"});
    cases.push_back({"--ops P --impl dary:65" + never + ".mp4", "--impl", "from 2 to 64"});
    cases.push_back({"--ops P --size 10x10" + never + ".mp4", "--size"});
    cases.push_back({"--ops P -q z" + never + ".mp4", "-q"});
    cases.push_back({"--ops P --progress loud" + never + ".mp4", "--progress"});
    cases.push_back({"--ops P --at -1" + never + ".png", "--at"});
    cases.push_back({"--ops P --last-frame --format gif" + never + ".png", "--format"});
    cases.push_back({"--ops P" + never + ".txt", "-o", "a .mp4 or .gif path"});
    // --code: one heap's pseudocode; none for arrays or several panels.
    cases.push_back({"--ops P --code --impl ordered" + never + ".mp4", "--code", "one heap"});
    cases.push_back({"--ops P --code --impl binary,dary:3" + never + ".mp4", "--code", "one heap"});
    return cases;
}

}  // namespace collide::test

// The queue strip beside a single box (--mode event --queue, with and without --code) is narrow
// at the small presets: its text (heading, pops, the heap's nodes, the event just popped,
// "+N below") never lies on other text nor outside the strip, and none is cut. Read back from
// --layout-json's "text_ink" (where each string's glyphs went).
#include <doctest/doctest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "../support/temp_dir.hpp"
#include "run_collide.hpp"
#include "thumbnail_layout.hpp"

using collide::test::run_collide;
using collide::test::TempDir;

namespace {

struct Box {
    double x0, y0, x1, y1;
};

Box box_of(const nlohmann::json& v) {
    return {v.at(0).get<double>(), v.at(1).get<double>(), v.at(2).get<double>(),
            v.at(3).get<double>()};
}

/// Overlap by more than a pixel's fraction (touching edges do not count).
bool overlap(const Box& a, const Box& b) {
    constexpr double eps = 0.01;
    return a.x0 < b.x1 - eps && b.x0 < a.x1 - eps && a.y0 < b.y1 - eps && b.y0 < a.y1 - eps;
}

bool inside(const Box& a, const Box& outer) {
    constexpr double eps = 0.01;
    return a.x0 >= outer.x0 - eps && a.x1 <= outer.x1 + eps && a.y0 >= outer.y0 - eps &&
           a.y1 <= outer.y1 + eps;
}

void check_strip(const TempDir& dir, const std::string& scene, const char* preset,
                 const char* options, const char* at = "0.5") {
    CAPTURE(scene);
    CAPTURE(preset);
    CAPTURE(options);
    CAPTURE(at);
    const nlohmann::json layout = thumbnail_layout(dir, scene, preset, options, at);
    const nlohmann::json* strip_slot = nullptr;
    for (const nlohmann::json& slot : layout.at("text"))
        if (slot.at("role") == "queue") strip_slot = &slot;
    REQUIRE(strip_slot != nullptr);
    const Box strip = box_of(strip_slot->at("rect"));
    const double lesson_px = strip_slot->at("pixel_height").get<double>();
    // The strip's text: every queue string whose middle is in the strip (a crowded box's disc
    // numbers, also queue text, stay off the strip).
    std::vector<std::pair<Box, std::string>> texts;
    for (const nlohmann::json& ink : layout.at("text_ink")) {
        if (ink.at("role") != "queue") continue;
        const Box b = box_of(ink.at("rect"));
        const double cx = 0.5 * (b.x0 + b.x1);
        const double cy = 0.5 * (b.y0 + b.y1);
        if (cx < strip.x0 || cx > strip.x1 || cy < strip.y0 || cy > strip.y1) continue;
        texts.emplace_back(b, ink.at("text").get<std::string>());
    }
    // The heading, a pop or the counts, and the root at least.
    CHECK(texts.size() >= 3);
    for (std::size_t i = 0; i < texts.size(); ++i) {
        const auto& [a, text] = texts[i];
        CAPTURE(text);
        CHECK(inside(a, strip));
        // Said whole: in fewer words where the strip is narrow, never cut with an ellipsis.
        CHECK(text.find("...") == std::string::npos);
        // At the lesson's text size (capitals 2.8 % of the frame height): never shrunk to fit.
        CHECK(a.y1 - a.y0 >= lesson_px - 0.5);
        for (std::size_t j = i + 1; j < texts.size(); ++j) {
            CAPTURE(texts[j].second);
            CHECK_FALSE(overlap(a, texts[j].first));
        }
    }
}

}  // namespace

TEST_CASE("the queue strip beside one box: no text on other text, all inside the strip") {
    TempDir dir("queue_strip");
    for (const std::string scene : {"dense-fluid", "gas", "billiards"})
        for (const char* preset : {"l", "m"})
            for (const char* options : {"--mode event --queue", "--mode event --queue --code"})
                check_strip(dir, scene, preset, options);
    // Late in a dense run the counts grow long ("316,487 pops, 65,796 stale" at t = 2): still
    // said whole, on two lines where one is too narrow.
    for (const char* preset : {"l", "m"})
        check_strip(dir, "dense-fluid", preset, "--mode event --queue", "2");
}

namespace {

/// The disc numbers a crowded box's queue drew outside it (queue text outside the strip, all
/// digits), each with where its plate went.
std::vector<std::pair<Box, std::string>> disc_numbers(const nlohmann::json& layout) {
    Box strip{};
    for (const nlohmann::json& slot : layout.at("text"))
        if (slot.at("role") == "queue") strip = box_of(slot.at("rect"));
    std::vector<std::pair<Box, std::string>> out;
    for (const nlohmann::json& label : layout.at("other_text")) {
        if (label.at("role") != "queue") continue;
        const Box b = box_of(label.at("rect"));
        const std::string text = label.at("text").get<std::string>();
        if (overlap(b, strip) || text.empty() ||
            text.find_first_not_of("0123456789") != std::string::npos)
            continue;
        out.emplace_back(b, text);
    }
    return out;
}

}  // namespace

TEST_CASE("dense-fluid at -q l numbers every disc of the listed collisions, as at -q m") {
    // The box is too crowded for a number beside a disc: every number goes outside it. The next
    // five collisions of a periodic box are five pairs, ten discs; -q l has the room -q m has.
    TempDir dir("queue_numbers");
    for (const char* options :
         {"--mode event --queue", "--mode event --queue --code", "--queue", "--queue --code"}) {
        CAPTURE(options);
        std::vector<std::string> at_m;
        for (const char* preset : {"m", "l"}) {
            CAPTURE(preset);
            const nlohmann::json layout = thumbnail_layout(dir, "dense-fluid", preset, options);
            const auto numbers = disc_numbers(layout);
            std::vector<std::string> texts;
            for (const auto& [plate, text] : numbers) texts.push_back(text);
            std::sort(texts.begin(), texts.end());
            CHECK(std::adjacent_find(texts.begin(), texts.end()) == texts.end());
            CHECK(texts.size() == 10);
            if (at_m.empty()) at_m = texts;
            CHECK(texts == at_m);
            // The strip's root ("806-849", its first pair drawn; the event just popped comes
            // after it) names two of them.
            bool root = false;
            for (const nlohmann::json& ink : layout.at("text_ink")) {
                const std::string text = ink.at("text").get<std::string>();
                const auto dash = text.find('-');
                if (ink.at("role") != "queue" || dash == std::string::npos ||
                    text.find_first_not_of("0123456789-") != std::string::npos)
                    continue;
                CAPTURE(text);
                CHECK(std::count(texts.begin(), texts.end(), text.substr(0, dash)) == 1);
                CHECK(std::count(texts.begin(), texts.end(), text.substr(dash + 1)) == 1);
                root = true;
                break;
            }
            CHECK(root);
            // Never one plate on another, never over the box.
            const Box box = box_of(layout.at("panels").back().at("box"));
            for (std::size_t i = 0; i < numbers.size(); ++i) {
                CAPTURE(numbers[i].second);
                CHECK_FALSE(overlap(numbers[i].first, box));
                for (std::size_t j = i + 1; j < numbers.size(); ++j)
                    CHECK_FALSE(overlap(numbers[i].first, numbers[j].first));
            }
        }
    }
}

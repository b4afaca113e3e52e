#include "cli_conventions.hpp"

#include <array>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

#ifndef COLLIDE_NO_VIDEO
extern "C" {
#include <libavcodec/version.h>
#include <libavfilter/version.h>
#include <libavformat/version.h>
#include <libavutil/version.h>
#include <libswscale/version.h>
}
#endif

#include "collide/scene/load.hpp"
#include "collide_build_info.hpp"

namespace collide::app {

namespace {

/// The words after "...not expected: " in CLI11's ExtrasError (its only record of them).
std::vector<std::string> unexpected_words(const std::string& message) {
    std::vector<std::string> words;
    const std::size_t colon = message.find("expected: ");
    if (colon == std::string::npos) return words;
    std::istringstream in(message.substr(colon + 10));
    for (std::string word; in >> word;) words.push_back(word);
    return words;
}

/// The long option of `app` (visible in its help) closest to `word` ("--durration=5").
std::string nearest_option(const CLI::App& app, std::string word) {
    word = word.substr(0, word.find('='));
    if (word.rfind("--", 0) != 0) return {};
    std::vector<std::string> names;
    for (const CLI::Option* option : app.get_options()) {
        if (option->get_group().empty()) continue;  // hidden
        for (const std::string& name : option->get_lnames()) names.push_back(name);
    }
    const std::string guess = nearest_name(std::string_view(word).substr(2), names);
    return guess.empty() ? std::string() : "--" + guess;
}

std::string nearest_subcommand(const CLI::App& root, const std::string& word) {
    std::vector<std::string> names;
    for (const CLI::App* command : root.get_subcommands([](const CLI::App*) { return true; }))
        names.push_back(command->get_name());
    return nearest_name(word, names);
}

}  // namespace

namespace {

/// The libav versions the drawing program was built with, or what the lean build writes.
std::string libav_text() {
#ifdef COLLIDE_NO_VIDEO
    return "none (built with -DCOLLIDE_VIDEO=OFF: PNG images and frames only, no MP4 or GIF)";
#else
    // Known at build time: `collide` links neither the renderer nor libav (it starts fast), and
    // collide-draw runs on the same major versions (their sonames).
    constexpr std::array<std::pair<const char*, const char*>, 5> libraries{{
        {"libavcodec", AV_STRINGIFY(LIBAVCODEC_VERSION)},
        {"libavformat", AV_STRINGIFY(LIBAVFORMAT_VERSION)},
        {"libavutil", AV_STRINGIFY(LIBAVUTIL_VERSION)},
        {"libswscale", AV_STRINGIFY(LIBSWSCALE_VERSION)},
        {"libavfilter", AV_STRINGIFY(LIBAVFILTER_VERSION)},
    }};
    std::string libav;
    for (const auto& [name, version] : libraries) {
        libav += (libav.empty() ? "" : ", ") + std::string(name) + " " + version;
    }
    return libav;
#endif
}

}  // namespace

std::string version_text() {
    const std::string libav = libav_text();
    const DataDir data = data_dir();
    return std::string("collide ") + COLLIDE_VERSION + " (git " + COLLIDE_GIT_REVISION + ")\n" +
           "GL backends: " + COLLIDE_GL_BACKENDS_TEXT + "\n" + "libav (built with): " + libav +
           "\n" + "data: " + data.path.string() + " (" + data.found_by + ")";
}

std::string typo_hint(const CLI::App& root, const CLI::ParseError& error) {
    if (dynamic_cast<const CLI::ExtrasError*>(&error) == nullptr) return {};
    const std::vector<CLI::App*>& given = root.get_subcommands();
    const CLI::App& app = given.empty() ? root : *given.front();
    for (const std::string& word : unexpected_words(error.what())) {
        const std::string guess = word.rfind('-', 0) == 0 ? nearest_option(app, word)
                                  : given.empty()         ? nearest_subcommand(root, word)
                                                          : std::string();
        if (!guess.empty()) return " (did you mean '" + guess + "'?)";
    }
    return {};
}

}  // namespace collide::app

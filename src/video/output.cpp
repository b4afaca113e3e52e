#include "collide/video/output.hpp"

#include <cstdio>

#include "collide/error.hpp"
#include "collide/io/file.hpp"

namespace collide::video {

void check_sequence_name(const std::filesystem::path& path) {
    // The frames' names add "_00000.png" to the directory's stem; NAME_MAX is 255 bytes.
    constexpr std::size_t name_max = 255;
    const std::string first = sequence_frame_name(sequence_stem(path), 0);
    if (first.size() > name_max) {
        throw_input_error("output '" + path.string() + "': the frames' names ('" +
                          first.substr(0, 20) + "...', " + std::to_string(first.size()) +
                          " bytes) would exceed the file name limit of 255 bytes; give the "
                          "directory a shorter name");
    }
}

void check_output_writable(const std::filesystem::path& path, bool directory_output) {
    if (directory_output) {
        check_sequence_name(path);
        const std::string stem = sequence_stem(path);
        io::check_output_directory(
            path, [stem](std::string_view name) { return is_sequence_frame_name(stem, name); });
        return;
    }
    io::OutputFile probe(path);
    probe.discard();
}

std::string sequence_frame_name(std::string_view stem, std::int64_t index) {
    char number[32];
    std::snprintf(number, sizeof number, "_%05lld.png", static_cast<long long>(index));
    return std::string(stem) + number;
}

bool is_sequence_frame_name(std::string_view stem, std::string_view name) {
    constexpr std::string_view extension = ".png";
    if (name.size() < stem.size() + 1 + 5 + extension.size()) return false;
    if (name.substr(0, stem.size()) != stem || name[stem.size()] != '_') return false;
    if (name.substr(name.size() - extension.size()) != extension) return false;
    const std::string_view digits =
        name.substr(stem.size() + 1, name.size() - stem.size() - 1 - extension.size());
    for (const char c : digits) {
        if (c < '0' || c > '9') return false;
    }
    return true;
}

bool is_any_sequence_frame_name(std::string_view name) {
    const std::size_t underscore = name.rfind('_');
    return underscore != std::string_view::npos && underscore > 0 &&
           is_sequence_frame_name(name.substr(0, underscore), name);
}

std::string sequence_stem(const std::filesystem::path& path) {
    std::filesystem::path p = path;
    while (!p.empty() && !p.has_filename() && p != p.root_path()) p = p.parent_path();
    return p.stem().string();
}

}  // namespace collide::video

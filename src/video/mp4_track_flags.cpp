// Reads the MP4's box tree far enough to find each track's header and handler, and clears the
// subtitle tracks' "enabled" flag in place (mp4_track_flags.hpp).
#include "mp4_track_flags.hpp"

#include <cstdint>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "collide/error.hpp"

namespace collide::video {

namespace {

/// A box of the tree: where its payload starts and ends (offsets into the buffer or file).
struct Box {
    std::string type;
    std::uint64_t payload = 0;
    std::uint64_t end = 0;
};

std::uint64_t big_endian(const unsigned char* bytes, int count) {
    std::uint64_t value = 0;
    for (int i = 0; i < count; ++i) value = (value << 8U) | bytes[i];
    return value;
}

/// The boxes directly inside [from, to) of `data`; stops at the first malformed one.
std::vector<Box> children(const std::vector<unsigned char>& data, std::uint64_t from,
                          std::uint64_t to) {
    std::vector<Box> out;
    std::uint64_t at = from;
    while (at + 8 <= to) {
        std::uint64_t size = big_endian(&data[at], 4);
        std::uint64_t header = 8;
        if (size == 1) {
            if (at + 16 > to) break;
            size = big_endian(&data[at + 8], 8);
            header = 16;
        } else if (size == 0) {
            size = to - at;  // to the end of the enclosing box
        }
        if (size < header || size > to - at) break;
        out.push_back(
            {std::string(reinterpret_cast<const char*>(&data[at + 4]), 4), at + header, at + size});
        at += size;
    }
    return out;
}

std::optional<Box> child(const std::vector<unsigned char>& data, const Box& parent,
                         std::string_view type) {
    for (const Box& box : children(data, parent.payload, parent.end)) {
        if (box.type == type) return box;
    }
    return std::nullopt;
}

/// Where the top-level 'moov' box lies in the file: its offset and size.
std::optional<std::pair<std::uint64_t, std::uint64_t>> find_moov(std::fstream& file,
                                                                 std::uint64_t file_size) {
    std::uint64_t at = 0;
    while (at + 8 <= file_size) {
        unsigned char head[16];
        file.seekg(static_cast<std::streamoff>(at));
        if (!file.read(reinterpret_cast<char*>(head), 8)) return std::nullopt;
        std::uint64_t size = big_endian(head, 4);
        if (size == 1) {
            if (!file.read(reinterpret_cast<char*>(head + 8), 8)) return std::nullopt;
            size = big_endian(head + 8, 8);
        } else if (size == 0) {
            size = file_size - at;
        }
        if (size < 8 || size > file_size - at) return std::nullopt;
        if (std::string_view(reinterpret_cast<const char*>(head + 4), 4) == "moov")
            return std::make_pair(at, size);
        at += size;
    }
    return std::nullopt;
}

}  // namespace

void disable_subtitle_tracks(const std::filesystem::path& path) {
    const std::string shown = "'" + path.string() + "'";
    std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
    if (!file) throw_runtime_error("cannot open " + shown + " to set its subtitle track");
    file.seekg(0, std::ios::end);
    const auto file_size = static_cast<std::uint64_t>(file.tellg());
    const auto moov = find_moov(file, file_size);
    if (!moov) throw_runtime_error(shown + " holds no MP4 index ('moov' box)");
    std::vector<unsigned char> data(moov->second);
    file.seekg(static_cast<std::streamoff>(moov->first));
    if (!file.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(data.size())))
        throw_runtime_error("cannot read the index of " + shown);
    const std::vector<Box> top = children(data, 0, data.size());
    if (top.empty() || top.front().type != "moov")
        throw_runtime_error(shown + " holds no MP4 index ('moov' box)");
    bool changed = false;
    for (const Box& trak : children(data, top.front().payload, top.front().end)) {
        if (trak.type != "trak") continue;
        const auto tkhd = child(data, trak, "tkhd");
        const auto mdia = child(data, trak, "mdia");
        const auto hdlr = mdia ? child(data, *mdia, "hdlr") : std::nullopt;
        // tkhd: version (1 byte), flags (3); hdlr: version and flags (4), pre-defined (4), type.
        if (!tkhd || !hdlr || tkhd->end - tkhd->payload < 4 || hdlr->end - hdlr->payload < 12)
            continue;
        const std::string_view handler(reinterpret_cast<const char*>(&data[hdlr->payload + 8]), 4);
        // 'sbtl': mov_text in an MP4. The chapter track is a QuickTime 'text' track: left alone.
        if (handler != "sbtl") continue;
        unsigned char& lowest_flags = data[tkhd->payload + 3];
        if ((lowest_flags & 0x01U) == 0) continue;
        lowest_flags = static_cast<unsigned char>(lowest_flags & ~0x01U);
        changed = true;
    }
    if (!changed) return;
    file.seekp(static_cast<std::streamoff>(moov->first));
    if (!file.write(reinterpret_cast<const char*>(data.data()),
                    static_cast<std::streamsize>(data.size())) ||
        !file.flush())
        throw_runtime_error("cannot write the index of " + shown);
}

}  // namespace collide::video

#include "collide/video/png.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "collide/error.hpp"
#include "collide/video/output.hpp"
#include "frame_sink.hpp"

namespace collide::video {
namespace {

void append_bytes(void* context, void* data, int size) {
    auto* bytes = static_cast<std::vector<unsigned char>*>(context);
    const auto* begin = static_cast<const unsigned char*>(data);
    bytes->insert(bytes->end(), begin, begin + size);
}

/// Writes `bytes` to `file`, checking every step (a full disk shows up at fwrite or fclose).
void write_all(const std::filesystem::path& file, const std::vector<unsigned char>& bytes,
               const std::filesystem::path& shown_as) {
    std::FILE* stream = std::fopen(file.c_str(), "wb");
    if (stream == nullptr) {
        throw_runtime_error("cannot write PNG '" + shown_as.string() +
                            "': " + std::strerror(errno));
    }
    const std::size_t written = std::fwrite(bytes.data(), 1, bytes.size(), stream);
    const int write_errno = errno;
    const bool closed = std::fclose(stream) == 0;
    if (written != bytes.size() || !closed) {
        throw_runtime_error("cannot write PNG '" + shown_as.string() +
                            "': " + std::strerror(written != bytes.size() ? write_errno : errno));
    }
}

}  // namespace

namespace detail {

void write_png_file(const Image& image, const std::filesystem::path& path,
                    const std::filesystem::path& shown_as) {
    // Encode to memory and write ourselves: stbi_write_png() ignores fwrite/fclose failures, which
    // would turn a full disk into a silently truncated file.
    std::vector<unsigned char> bytes;
    const int ok = stbi_write_png_to_func(append_bytes, &bytes, image.width, image.height, 4,
                                          image.rgba.data(), static_cast<int>(image.stride()));
    if (ok == 0) throw_runtime_error("cannot encode PNG '" + shown_as.string() + "'");
    write_all(path, bytes, shown_as);
}

namespace {

/// Writes each frame as its own PNG inside the writer's temporary directory.
class PngSequenceSink final : public FrameSink {
  public:
    PngSequenceSink(std::string stem, std::filesystem::path directory)
        : stem_(std::move(stem)), directory_(std::move(directory)) {}

    void consume(const Image& frame) override {
        char number[16];
        std::snprintf(number, sizeof number, "_%05lld.png", static_cast<long long>(index_));
        const std::string name = stem_ + number;
        write_png_file(frame, directory_ / name, name);
        ++index_;
    }
    void finish() override {}  // every file is complete when consume() returns

  private:
    std::string stem_;
    std::filesystem::path directory_;
    std::int64_t index_ = 0;
};

}  // namespace

std::unique_ptr<FrameSink> make_png_sequence_sink(const std::string& stem,
                                                  const std::filesystem::path& directory) {
    return std::make_unique<PngSequenceSink>(stem, directory);
}

}  // namespace detail

void write_png(const Image& image, const std::filesystem::path& path) {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgba.size() != image.stride() * static_cast<std::size_t>(image.height)) {
        throw_runtime_error("write_png '" + path.string() + "': image is empty or inconsistent (" +
                            std::to_string(image.width) + "x" + std::to_string(image.height) + ")");
    }
    TemporaryOutput temporary(path, TemporaryOutput::Kind::file);
    detail::write_png_file(image, temporary.path(), path);
    temporary.commit();
}

Image read_png(const std::filesystem::path& path) {
    int width = 0;
    int height = 0;
    int channels_in_file = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load(path.c_str(), &width, &height, &channels_in_file, 4), stbi_image_free);
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        throw_input_error("cannot read PNG '" + path.string() +
                          "': " + (reason != nullptr ? reason : "unknown error"));
    }
    Image image(width, height);
    std::copy_n(pixels.get(), image.rgba.size(), image.rgba.begin());
    return image;
}

}  // namespace collide::video

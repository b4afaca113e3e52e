#include "collide/video/png.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <future>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "collide/error.hpp"
#include "collide/io/file.hpp"
#include "collide/video/output.hpp"
#include "frame_sink.hpp"

namespace collide::video {
namespace {

void append_bytes(void* context, void* data, int size) {
    auto* bytes = static_cast<std::vector<unsigned char>*>(context);
    const auto* begin = static_cast<const unsigned char*>(data);
    bytes->insert(bytes->end(), begin, begin + size);
}

}  // namespace

namespace detail {

std::vector<unsigned char> encode_png(const Image& image, const std::filesystem::path& shown_as) {
    // Encode to memory and write ourselves: stbi_write_png() ignores fwrite/fclose failures, which
    // would turn a full disk into a silently truncated file.
    std::vector<unsigned char> bytes;
    const int ok = stbi_write_png_to_func(append_bytes, &bytes, image.width, image.height, 4,
                                          image.rgba.data(), static_cast<int>(image.stride()));
    if (ok == 0) throw_runtime_error("cannot encode PNG '" + shown_as.string() + "'");
    return bytes;
}

namespace {

/// Writes each frame as its own PNG inside the writer's temporary directory.
class PngSequenceSink final : public FrameSink {
  public:
    PngSequenceSink(std::string stem, const io::OutputDirectory& directory)
        : stem_(std::move(stem)), directory_(directory) {}

    void consume(const Image& frame) override {
        const std::string name = sequence_frame_name(stem_, index_);
        const std::vector<unsigned char> bytes = encode_png(frame, name);
        io::File file = directory_.create_file(name);
        file.write_all(bytes.data(), bytes.size(), name);
        file.close(name);
        ++index_;
    }
    void finish() override {}  // every file is complete when consume() returns

  private:
    std::string stem_;
    const io::OutputDirectory& directory_;
    std::int64_t index_ = 0;
};

}  // namespace

std::unique_ptr<FrameSink> make_png_sequence_sink(const std::string& stem,
                                                  const io::OutputDirectory& directory) {
    return std::make_unique<PngSequenceSink>(stem, directory);
}

}  // namespace detail

std::vector<unsigned char> png_bytes(const Image& image, const std::filesystem::path& shown_as) {
    return detail::encode_png(image, shown_as);
}

void write_png(const Image& image, const std::filesystem::path& path) {
    write_png_uncommitted(image, path).commit();
}

io::OutputFile write_png_uncommitted(const Image& image, const std::filesystem::path& path) {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgba.size() != image.stride() * static_cast<std::size_t>(image.height)) {
        throw_runtime_error("write_png '" + path.string() + "': image is empty or inconsistent (" +
                            std::to_string(image.width) + "x" + std::to_string(image.height) + ")");
    }
    const std::vector<unsigned char> bytes = detail::encode_png(image, path);
    io::OutputFile file(path);
    file.write(bytes.data(), bytes.size());
    return file;
}

io::OutputFile write_png_uncommitted(Image&& image, const std::filesystem::path& path,
                                     const std::atomic<bool>& cancel) {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgba.size() != image.stride() * static_cast<std::size_t>(image.height)) {
        throw_runtime_error("write_png '" + path.string() + "': image is empty or inconsistent (" +
                            std::to_string(image.width) + "x" + std::to_string(image.height) + ")");
    }
    // The task owns the image and the future's state owns the bytes, so the detached thread
    // touches nothing of this frame once it is abandoned.
    auto owned = std::make_shared<const Image>(std::move(image));
    std::packaged_task<std::vector<unsigned char>()> task(
        [owned, path] { return detail::encode_png(*owned, path); });
    std::future<std::vector<unsigned char>> encoded = task.get_future();
    std::thread(std::move(task)).detach();
    while (encoded.wait_for(std::chrono::milliseconds(10)) != std::future_status::ready) {
        if (cancel.load()) throw_runtime_error("interrupted; nothing was written");
    }
    const std::vector<unsigned char> bytes = encoded.get();
    io::OutputFile file(path);
    file.write(bytes.data(), bytes.size());
    return file;
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

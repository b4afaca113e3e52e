#include "collide/video/png.hpp"

#include <fcntl.h>
#include <stb_image.h>
#include <stb_image_write.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <future>
#include <memory>
#include <new>
#include <string>
#include <string_view>
#include <system_error>
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

bool is_opaque(const Image& image) {
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) {
        if (image.rgba[i] != 255) return false;
    }
    return true;
}

/// The RGB channels of `image`, packed (3 bytes a pixel, rows top-down).
std::vector<unsigned char> rgb_of(const Image& image) {
    std::vector<unsigned char> rgb(image.rgba.size() / 4 * 3);
    for (std::size_t from = 0, to = 0; from + 3 < image.rgba.size(); from += 4, to += 3) {
        rgb[to] = image.rgba[from];
        rgb[to + 1] = image.rgba[from + 1];
        rgb[to + 2] = image.rgba[from + 2];
    }
    return rgb;
}

}  // namespace

namespace detail {

std::vector<unsigned char> encode_png(const Image& image, const std::filesystem::path& shown_as) {
    // Encode to memory and write ourselves: stbi_write_png() ignores fwrite/fclose failures, which
    // would turn a full disk into a silently truncated file.
    std::vector<unsigned char> bytes;
    int ok = 0;
    if (is_opaque(image)) {
        // Every frame collide draws is opaque: RGB is a quarter fewer bytes to compress and about
        // a fifth smaller on disk than RGBA with an alpha of 255 everywhere.
        const std::vector<unsigned char> rgb = rgb_of(image);
        ok = stbi_write_png_to_func(append_bytes, &bytes, image.width, image.height, 3, rgb.data(),
                                    image.width * 3);
    } else {
        ok = stbi_write_png_to_func(append_bytes, &bytes, image.width, image.height, 4,
                                    image.rgba.data(), static_cast<int>(image.stride()));
    }
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

namespace {

std::string error_text(int error) {
    return std::error_code(error, std::generic_category()).message();
}

/// The whole of the regular file at `path`, at most max_png_file_bytes. Opens without blocking
/// (a FIFO would wait for a writer forever) and checks what it opened (fstat on the descriptor),
/// so a FIFO or a device is refused at once. Throws Error(input) naming the file.
std::vector<unsigned char> read_image_file(const std::filesystem::path& path) {
    const std::string name = path.string();
    io::File file(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
    if (!file) throw_input_error("cannot read PNG '" + name + "': " + error_text(errno));
    struct stat info {};
    if (::fstat(file.get(), &info) != 0) {
        throw_input_error("cannot read PNG '" + name + "': " + error_text(errno));
    }
    if (!S_ISREG(info.st_mode)) {
        throw_input_error("cannot read PNG '" + name + "': " + io::file_type_name(info.st_mode) +
                          ", not a regular file: images are read from regular files only");
    }
    const auto too_large = [&] {
        throw_input_error("cannot read PNG '" + name + "': larger than " +
                          std::to_string(max_png_file_bytes >> 20) +
                          " MiB, the most an image file may have (docs/limits.md)");
    };
    if (static_cast<std::uintmax_t>(info.st_size) > max_png_file_bytes) too_large();
    // Read to the end rather than st_size bytes (the file may grow meanwhile), never past the cap.
    std::vector<unsigned char> bytes(static_cast<std::size_t>(info.st_size) + 1);
    std::size_t used = 0;
    for (;;) {
        if (used == bytes.size()) {
            if (used > max_png_file_bytes) too_large();
            bytes.resize(std::min<std::size_t>(2 * used + 4096, max_png_file_bytes + 1));
        }
        const ssize_t got = ::read(file.get(), bytes.data() + used, bytes.size() - used);
        if (got < 0) {
            if (errno == EINTR) continue;
            throw_input_error("cannot read PNG '" + name + "': " + error_text(errno));
        }
        if (got == 0) break;
        used += static_cast<std::size_t>(got);
    }
    if (used > max_png_file_bytes) too_large();
    bytes.resize(used);
    return bytes;
}

constexpr std::array<unsigned char, 8> png_signature{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

bool starts_with(const std::vector<unsigned char>& bytes, std::string_view prefix) {
    return bytes.size() >= prefix.size() &&
           std::equal(prefix.begin(), prefix.end(), bytes.begin(),
                      [](char a, unsigned char b) { return static_cast<unsigned char>(a) == b; });
}

/// What a file that is not a PNG seems to be, for the message ("" when unknown).
std::string other_format(const std::vector<unsigned char>& bytes) {
    if (starts_with(bytes, "\xff\xd8\xff")) return " (it is a JPEG image)";
    if (starts_with(bytes, "GIF8")) return " (it is a GIF image)";
    if (starts_with(bytes, "BM")) return " (it looks like a BMP image)";
    if (starts_with(bytes, "RIFF")) return " (it looks like a WebP image)";
    return "";
}

/// Refuses `bytes` unless they start like a PNG file; says what they look like otherwise.
void require_png_signature(const std::vector<unsigned char>& bytes, const std::string& name) {
    if (bytes.empty()) throw_input_error("cannot read PNG '" + name + "': the file is empty");
    if (bytes.size() < png_signature.size() ||
        !std::equal(png_signature.begin(), png_signature.end(), bytes.begin())) {
        throw_input_error("cannot read PNG '" + name + "': not a PNG image" + other_format(bytes));
    }
}

struct PngSize {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
};

/// The size a PNG's header chunk (IHDR, always first) declares, read from the bytes themselves.
PngSize png_header_size(const std::vector<unsigned char>& bytes, const std::string& name) {
    // Signature (8), chunk length (4), "IHDR" (4), width (4), height (4), big-endian.
    constexpr std::size_t ihdr_type = 12;
    constexpr std::size_t ihdr_width = 16;
    if (bytes.size() < ihdr_width + 8 ||
        !std::equal(bytes.begin() + ihdr_type, bytes.begin() + ihdr_type + 4, "IHDR")) {
        throw_input_error("cannot read PNG '" + name + "': a damaged PNG (no header chunk)");
    }
    const auto be32 = [&](std::size_t at) {
        return std::uint32_t{bytes[at]} << 24 | std::uint32_t{bytes[at + 1]} << 16 |
               std::uint32_t{bytes[at + 2]} << 8 | std::uint32_t{bytes[at + 3]};
    };
    return {be32(ihdr_width), be32(ihdr_width + 4)};
}

}  // namespace

Image read_png(const std::filesystem::path& path) {
    const std::string name = path.string();
    const std::vector<unsigned char> bytes = read_image_file(path);
    require_png_signature(bytes, name);
    // The header first: a small file can describe a huge image (a 1-bit 23000 x 23000 PNG is
    // under 100 kB and would take 2 GB and a minute to decode).
    const PngSize declared = png_header_size(bytes, name);
    constexpr auto side = static_cast<std::uint32_t>(max_png_side);
    if (declared.width > side || declared.height > side) {
        throw_input_error("cannot read PNG '" + name + "': " + std::to_string(declared.width) +
                          "x" + std::to_string(declared.height) +
                          " pixels; images are read up to " + std::to_string(max_png_side) + "x" +
                          std::to_string(max_png_side) +
                          ", the largest frame collide renders (docs/limits.md)");
    }
    const int size = static_cast<int>(bytes.size());  // <= max_png_file_bytes < INT_MAX
    int width = 0;
    int height = 0;
    int channels_in_file = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(bytes.data(), size, &width, &height, &channels_in_file, 4),
        stbi_image_free);
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        // stb's word for a failed malloc: out of memory, not bad input (main says what to do).
        if (reason != nullptr && std::strcmp(reason, "outofmem") == 0) throw std::bad_alloc();
        throw_input_error("cannot read PNG '" + name + "': a damaged PNG (" +
                          (reason != nullptr ? reason : "unknown error") + ")");
    }
    Image image(width, height);
    std::copy_n(pixels.get(), image.rgba.size(), image.rgba.begin());
    return image;
}

}  // namespace collide::video

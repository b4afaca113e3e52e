#pragma once
/// \file
/// Single PNG files (thumbnails, PNG sequences, test fixtures) through stb_image(_write).

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "collide/image.hpp"
#include "collide/io/file.hpp"

namespace collide::video {

/// The widest and tallest image read_png decodes: the largest frame collide renders (--size's
/// bound). A PNG's header is read first, so a small file that describes a huge image is refused
/// before any pixel is decoded.
inline constexpr int max_png_side = 8192;
/// The largest PNG file read_png reads (an 8192 x 8192 RGBA image stored uncompressed is 256 MiB).
inline constexpr std::uintmax_t max_png_file_bytes = std::uintmax_t{512} << 20;

/// Writes `image` as a PNG at `path` (RGB when every pixel is opaque, RGBA otherwise), atomically:
/// the bytes go to a temporary file beside `path` that is renamed over it only once complete, so
/// `path` holds either its old content or the whole new image. Cost: O(width * height) (zlib at
/// stb's default level). Throws Error(input) naming the path if its directory does not exist or is
/// not writable, Error(runtime) if the image is empty/inconsistent or the write fails (e.g. a full
/// disk).
void write_png(const Image& image, const std::filesystem::path& path);
/// write_png without the final step: the whole PNG in its temporary, put in place by the
/// returned file's commit() (for a run that commits its outputs only once all are written).
[[nodiscard]] io::OutputFile write_png_uncommitted(const Image& image,
                                                   const std::filesystem::path& path);
/// The same for an image the caller gives up, encoded on a thread of its own while this one
/// polls `cancel` every 10 ms: a large frame takes seconds to compress (8192x4608: about 5 s),
/// and an interrupt must end the run within a second. Once `cancel` is set it throws
/// Error(runtime) "interrupted; nothing was written" at once, writes nothing, and leaves the
/// encoding to finish on its detached thread (which owns the image and its result) and be
/// dropped: the program is about to exit by its signal.
[[nodiscard]] io::OutputFile write_png_uncommitted(Image&& image, const std::filesystem::path& path,
                                                   const std::atomic<bool>& cancel);

/// `image` as the bytes of a PNG file (RGB when opaque, as write_png) (for a caller that writes
/// them where it chooses, e.g. into an io::OutputDirectory). `shown_as` names it in the error.
/// Throws Error(runtime) if the image cannot be encoded.
[[nodiscard]] std::vector<unsigned char> png_bytes(const Image& image,
                                                   const std::filesystem::path& shown_as);

/// Reads a PNG (any bit depth / channel count stb understands) as RGBA8, rows top-down.
/// Throws Error(input) naming the path if it cannot be opened, is not a regular file (a FIFO or a
/// device is refused at once, without reading), is larger than max_png_file_bytes, is not a PNG
/// (saying what it seems to be: JPEG, GIF...), describes an image wider or taller than
/// max_png_side, or cannot be decoded; std::bad_alloc when memory runs out.
[[nodiscard]] Image read_png(const std::filesystem::path& path);

}  // namespace collide::video

// GIF (palette per clip, rate cap) and PNG (single files, sequences) round trips.

#include <doctest/doctest.h>
#include <sys/stat.h>

#include "../support/png_bytes.hpp"
#include "collide/error.hpp"
#include "collide/video/png.hpp"
#include "collide/video/video_writer.hpp"
#include "video_test_support.hpp"

using namespace collide::video;
using namespace collide::video::testing;

TEST_CASE("write_png/read_png round trip is exact and leaves no temporary") {
    ScratchDirectory dir;
    const collide::Image image = test_pattern(33, 17, 2);
    write_png(image, dir / "thumb.png");
    const collide::Image back = read_png(dir / "thumb.png");
    CHECK(back.width == 33);
    CHECK(back.height == 17);
    CHECK(back.rgba == image.rgba);
    CHECK(dir.entries() == std::vector<std::string>{"thumb.png"});
}

TEST_CASE("write_png replaces an existing file, and a failed write keeps it") {
    ScratchDirectory dir;
    const auto path = dir / "thumb.png";
    write_bytes(path, "old content");
    CHECK_THROWS_AS(write_png(collide::Image{}, path), collide::Error);  // empty image
    CHECK(read_bytes(path) == "old content");
    write_png(test_pattern(8, 8, 0), path);
    CHECK(read_png(path).rgba == test_pattern(8, 8, 0).rgba);
}

TEST_CASE("read_png of a missing or corrupt file is an input error naming it") {
    ScratchDirectory dir;
    write_bytes(dir / "bad.png", "not a png");
    for (const char* name : {"missing.png", "bad.png"}) {
        try {
            (void)read_png(dir / name);
            FAIL("no error");
        } catch (const collide::Error& e) {
            CHECK(e.kind() == collide::ErrorKind::input);
            CHECK(std::string(e.what()).find(name) != std::string::npos);
        }
    }
}

namespace {

/// The colour type byte of a PNG file's IHDR chunk: 2 RGB, 6 RGBA.
int png_colour_type(const std::string& bytes) {
    REQUIRE(bytes.size() > 25);
    REQUIRE(bytes.compare(12, 4, "IHDR") == 0);
    return static_cast<unsigned char>(bytes[25]);
}

std::string input_error_of(const std::filesystem::path& path) {
    try {
        (void)read_png(path);
    } catch (const collide::Error& e) {
        CHECK(e.kind() == collide::ErrorKind::input);
        CHECK(std::string(e.what()).find(path.string()) != std::string::npos);
        return e.what();
    }
    FAIL("no error reading " << path);
    return {};
}

}  // namespace

TEST_CASE("write_png stores an opaque image as RGB and one with any transparency as RGBA") {
    ScratchDirectory dir;
    collide::Image image = test_pattern(40, 30, 1);
    write_png(image, dir / "opaque.png");
    CHECK(png_colour_type(read_bytes(dir / "opaque.png")) == 2);
    CHECK(read_png(dir / "opaque.png").rgba == image.rgba);  // alpha read back as 255
    // One pixel short of opaque anywhere (here the last) keeps the alpha channel, exactly.
    image.rgba.back() = 254;
    write_png(image, dir / "alpha.png");
    CHECK(png_colour_type(read_bytes(dir / "alpha.png")) == 6);
    CHECK(read_png(dir / "alpha.png").rgba == image.rgba);
    CHECK(read_bytes(dir / "opaque.png").size() < read_bytes(dir / "alpha.png").size());
    // The bytes for a caller that writes them itself follow the same rule.
    CHECK(png_colour_type(std::string([&] {
              const auto b = png_bytes(test_pattern(9, 9, 0), "x.png");
              return std::string(b.begin(), b.end());
          }())) == 2);
}

TEST_CASE("read_png refuses at once what is not a PNG file, saying what it is") {
    ScratchDirectory dir;
    REQUIRE(::mkfifo((dir / "fifo.png").c_str(), 0600) == 0);
    CHECK(input_error_of(dir / "fifo.png").find("FIFO") != std::string::npos);  // never blocks
    CHECK(input_error_of("/dev/null").find("character device") != std::string::npos);
    std::filesystem::create_directory(dir / "folder.png");
    CHECK(input_error_of(dir / "folder.png").find("directory") != std::string::npos);
    write_bytes(dir / "empty.png", "");
    CHECK(input_error_of(dir / "empty.png").find("empty") != std::string::npos);
    write_bytes(dir / "photo.png", std::string("\xff\xd8\xff\xe0\x00\x10JFIF", 10));
    CHECK(input_error_of(dir / "photo.png").find("not a PNG image (it is a JPEG image)") !=
          std::string::npos);
    write_bytes(dir / "anim.png", "GIF89a....");
    CHECK(input_error_of(dir / "anim.png").find("GIF") != std::string::npos);
    // A PNG cut short after its header: damaged, not a crash.
    const std::vector<unsigned char> whole = png_bytes(test_pattern(16, 16, 0), "t.png");
    write_bytes(dir / "cut.png", std::string(whole.begin(), whole.begin() + 40));
    CHECK(input_error_of(dir / "cut.png").find("damaged") != std::string::npos);
}

TEST_CASE("read_png refuses an image wider or taller than the largest frame before decoding it") {
    ScratchDirectory dir;
    for (const auto& [w, h] : {std::pair<std::uint32_t, std::uint32_t>{23000, 23000},
                               {max_png_side + 1, 16},
                               {16, max_png_side + 1},
                               {4000000000u, 1}}) {
        CAPTURE(w);
        CAPTURE(h);
        write_bytes(dir / "huge.png", collide::test::png_header_only(w, h));
        const std::string message = input_error_of(dir / "huge.png");
        CHECK(message.find(std::to_string(w) + "x" + std::to_string(h)) != std::string::npos);
        CHECK(message.find("8192x8192") != std::string::npos);
    }
}

TEST_CASE("PNG sequence: zero-padded names in a directory, exact pixels, old sequence replaced") {
    ScratchDirectory dir;
    const auto path = dir / "frames";
    std::filesystem::create_directory(path);
    for (int i = 0; i < 5; ++i) {
        write_bytes(path / ("frames_0000" + std::to_string(i) + ".png"), "from an older run");
    }

    VideoOptions options;
    options.path = path;
    options.format = VideoFormat::png_sequence;
    options.width = 40;
    options.height = 30;
    VideoWriter writer(options);
    for (int i = 0; i < 3; ++i) writer.write(test_pattern(40, 30, i));
    // Until finish() the old directory stays as it was.
    CHECK(read_bytes(path / "frames_00004.png") == "from an older run");
    writer.finish();

    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(path)) {
        names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    // The whole earlier sequence is replaced: no frame 3 or 4 of it is left.
    CHECK(names ==
          std::vector<std::string>{"frames_00000.png", "frames_00001.png", "frames_00002.png"});
    for (int i = 0; i < 3; ++i) {
        CHECK(read_png(path / names[i]).rgba == test_pattern(40, 30, i).rgba);
    }
    CHECK(dir.entries() == std::vector<std::string>{"frames"});
}

TEST_CASE("PNG sequence: a directory holding anything else is refused and left untouched") {
    ScratchDirectory dir;
    const auto path = dir / "out";
    std::filesystem::create_directory(path);
    write_bytes(path / "gas.mp4", "a video the user made earlier");
    write_bytes(path / "out_00000.png", "a frame");
    VideoOptions options;
    options.path = path;
    options.format = VideoFormat::png_sequence;
    options.width = 40;
    options.height = 30;
    try {
        VideoWriter writer(options);
        FAIL("accepted a directory with other files");
    } catch (const collide::Error& e) {
        CHECK(e.kind() == collide::ErrorKind::input);
        CHECK(std::string(e.what()).find("'gas.mp4'") != std::string::npos);
    }
    CHECK(read_bytes(path / "gas.mp4") == "a video the user made earlier");
    CHECK(read_bytes(path / "out_00000.png") == "a frame");
    CHECK(dir.entries() == std::vector<std::string>{"out"});
}

TEST_CASE("GIF: generated palette, frame rate capped by dropping frames evenly") {
    set_libav_verbose(false);
    ScratchDirectory dir;
    VideoOptions options;
    options.path = dir / "slide.gif";
    options.format = VideoFormat::gif;
    options.width = 160;
    options.height = 90;
    options.fps = 50;  // above the cap: every 2nd frame is kept, 25 fps
    VideoWriter writer(options);
    CHECK(writer.output_fps() == doctest::Approx(25.0));
    REQUIRE(writer.notices().size() == 1);
    CHECK(writer.notices()[0].find("50 to 25 fps") != std::string::npos);
    constexpr int frames = 10;
    for (int i = 0; i < frames; ++i) writer.write(test_pattern(160, 90, i));
    writer.finish();

    const Decoded decoded = decode_file(options.path);
    CHECK(decoded.codec == "gif");
    CHECK(decoded.width == 160);
    CHECK(decoded.height == 90);
    REQUIRE(decoded.frames.size() == frames / 2);
    // Kept frames are the even ones; 4/100 s apart.
    for (std::size_t i = 0; i < decoded.frames.size(); ++i) {
        const double quality = psnr_rgb(test_pattern(160, 90, 2 * int(i)), decoded.frames[i]);
        CHECK(quality >= 28.0);
    }
    for (std::size_t i = 1; i < decoded.pts.size(); ++i) {
        CHECK(double(decoded.pts[i] - decoded.pts[i - 1]) * av_q2d(decoded.time_base) ==
              doctest::Approx(0.04));
    }
    CHECK(dir.entries() == std::vector<std::string>{"slide.gif"});
}

TEST_CASE("GIF at a low frame rate keeps every frame and says nothing") {
    set_libav_verbose(false);
    ScratchDirectory dir;
    VideoOptions options;
    options.path = dir / "slow.gif";
    options.format = VideoFormat::gif;
    options.width = 64;
    options.height = 48;
    options.fps = 10;
    VideoWriter writer(options);
    CHECK(writer.notices().empty());
    for (int i = 0; i < 3; ++i) writer.write(test_pattern(64, 48, i));
    writer.finish();
    CHECK(decode_file(options.path).frames.size() == 3);
}

TEST_CASE("finished outputs get ordinary permissions (umask), not the temporaries' private ones") {
    const mode_t previous = umask(022);
    ScratchDirectory dir;
    write_png(test_pattern(4, 4, 0), dir / "thumb.png");
    VideoOptions options;
    options.path = dir / "seq";
    options.format = VideoFormat::png_sequence;
    options.width = 4;
    options.height = 4;
    VideoWriter writer(options);
    writer.write(test_pattern(4, 4, 0));
    writer.finish();
    umask(previous);
    using std::filesystem::perms;
    CHECK((std::filesystem::status(dir / "thumb.png").permissions() & perms::all) ==
          (perms::owner_read | perms::owner_write | perms::group_read | perms::others_read));
    CHECK((std::filesystem::status(dir / "seq").permissions() & perms::all) ==
          (perms::owner_all | perms::group_read | perms::group_exec | perms::others_read |
           perms::others_exec));
}

TEST_CASE("PNG sequence: a directory name too long for its frames' names is refused up front") {
    ScratchDirectory dir;
    VideoOptions options;
    options.path = dir / std::string(250, 'd');  // a legal name, but d..d_00000.png is not
    options.format = VideoFormat::png_sequence;
    options.width = 40;
    options.height = 30;
    try {
        VideoWriter writer(options);
        FAIL("accepted");
    } catch (const collide::Error& e) {
        CHECK(e.kind() == collide::ErrorKind::input);
        CHECK(std::string(e.what()).find("shorter name") != std::string::npos);
    }
    CHECK(dir.entries().empty());
    options.path = dir / std::string(240, 'd');
    VideoWriter writer(options);
    writer.write(test_pattern(40, 30, 0));
    writer.finish();
    CHECK(dir.entries() == std::vector<std::string>{std::string(240, 'd')});
}

// Error paths: bad options, unwritable destinations, missing encoders, wrong frame sizes, and
// interruption (cancel hook in-process, SIGINT/SIGTERM to a child process) leaving no partial
// output and keeping what was at the destination before.

#include <doctest/doctest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>

#include "../support/signal_child.hpp"
#include "collide/error.hpp"
#include "collide/video/output.hpp"
#include "collide/video/video_writer.hpp"
#include "video_test_support.hpp"

using namespace collide::video;
using namespace collide::video::testing;

namespace {

VideoOptions small_options(const std::filesystem::path& path) {
    set_libav_verbose(false);
    VideoOptions options;
    options.path = path;
    options.width = 160;
    options.height = 90;
    return options;
}

/// Runs `action`, expecting collide::Error of `kind` whose message contains `needle`.
template <typename Action>
void check_error(Action action, collide::ErrorKind kind, const std::string& needle) {
    try {
        action();
        FAIL("expected collide::Error containing '" << needle << "'");
    } catch (const collide::Error& e) {
        CHECK(e.kind() == kind);
        CHECK_MESSAGE(std::string(e.what()).find(needle) != std::string::npos, e.what());
    }
}

}  // namespace

TEST_CASE("validate() names the bad field") {
    VideoOptions options = small_options("out.mp4");
    CHECK_NOTHROW(options.validate());
    auto expect = [&](VideoOptions bad, const std::string& field) {
        check_error([&] { bad.validate(); }, collide::ErrorKind::input, field);
    };
    VideoOptions bad = options;
    bad.width = 0;
    expect(bad, "video.width");
    bad = options;
    bad.height = 9000;
    expect(bad, "video.height");
    bad = options;
    bad.fps = 0;
    expect(bad, "video.fps");
    bad = options;
    bad.crf = 52;
    expect(bad, "video.crf");
    bad.codec = VideoCodec::av1;  // AV1 accepts up to 63
    CHECK_NOTHROW(bad.validate());
    bad = options;
    bad.preset = "warp";
    expect(bad, "video.preset");
    bad.codec = VideoCodec::av1;
    bad.preset = "veryfast";
    expect(bad, "video.preset");
    bad.preset = std::string("8");  // not = "8": GCC 12 -O2 warns falsely (-Wrestrict, PR 105329)
    CHECK_NOTHROW(bad.validate());
    bad = options;
    bad.path.clear();
    expect(bad, "video.path");
}

TEST_CASE("format and codec names parse, and bad ones name the field") {
    CHECK(parse_video_format("MP4") == VideoFormat::mp4);
    CHECK(parse_video_format("gif") == VideoFormat::gif);
    CHECK(parse_video_format("png") == VideoFormat::png_sequence);
    CHECK(parse_video_codec("h265") == VideoCodec::hevc);
    CHECK(parse_video_codec("av1") == VideoCodec::av1);
    check_error([] { (void)parse_video_codec("vp9", "--codec"); }, collide::ErrorKind::input,
                "--codec");
    check_error([] { (void)parse_video_format("avi", "--format"); }, collide::ErrorKind::input,
                "avi");
}

TEST_CASE("unwritable destinations are input errors naming the path, before any frame") {
    ScratchDirectory dir;
    const auto missing = dir / "no-such-dir" / "out.mp4";
    check_error([&] { check_output_writable(missing); }, collide::ErrorKind::input,
                missing.string());
    check_error([&] { VideoWriter writer(small_options(missing)); }, collide::ErrorKind::input,
                "does not exist");

    write_bytes(dir / "plain-file", "x");
    const auto under_file = dir / "plain-file" / "out.mp4";
    check_error([&] { check_output_writable(under_file); }, collide::ErrorKind::input,
                "not a directory");

    std::filesystem::create_directory(dir / "a-directory");
    check_error([&] { check_output_writable(dir / "a-directory"); }, collide::ErrorKind::input,
                "is an existing directory");

    if (geteuid() != 0) {  // root writes through permission bits
        std::filesystem::create_directory(dir / "read-only");
        std::filesystem::permissions(dir / "read-only", std::filesystem::perms::owner_read |
                                                            std::filesystem::perms::owner_exec);
        check_error([&] { check_output_writable(dir / "read-only" / "out.mp4"); },
                    collide::ErrorKind::input, "cannot create a file");
    }
    CHECK_NOTHROW(check_output_writable(dir / "fine.mp4"));
    CHECK_FALSE(std::filesystem::exists(dir / "fine.mp4"));  // the probe leaves nothing behind
}

TEST_CASE("a missing encoder is a clear runtime error and leaves nothing behind") {
    ScratchDirectory dir;
    VideoOptions options = small_options(dir / "out.mp4");
    options.encoder = "libdoesnotexist";
    check_error([&] { VideoWriter writer(options); }, collide::ErrorKind::runtime,
                "video encoder 'libdoesnotexist' (for h264) is not available");
    CHECK(dir.entries().empty());
}

TEST_CASE("frames of the wrong size are rejected") {
    ScratchDirectory dir;
    VideoWriter writer(small_options(dir / "out.mp4"));
    check_error([&] { writer.write(collide::Image(100, 90)); }, collide::ErrorKind::runtime,
                "expected 160x90");
}

TEST_CASE("finish() without frames fails and keeps the old destination") {
    ScratchDirectory dir;
    write_bytes(dir / "out.mp4", "previous video");
    {
        VideoWriter writer(small_options(dir / "out.mp4"));
        check_error([&] { writer.finish(); }, collide::ErrorKind::runtime, "no frames");
    }
    CHECK(read_bytes(dir / "out.mp4") == "previous video");
    CHECK(dir.entries() == std::vector<std::string>{"out.mp4"});
}

TEST_CASE("a writer destroyed without finish() deletes its temporary and keeps the destination") {
    ScratchDirectory dir;
    write_bytes(dir / "out.mp4", "previous video");
    {
        VideoWriter writer(small_options(dir / "out.mp4"));
        for (int i = 0; i < 3; ++i) writer.write(test_pattern(160, 90, i));
        // The destination, and at most our hidden temporary (none where O_TMPFILE works).
        for (const std::string& name : dir.entries()) CHECK((name == "out.mp4" || name[0] == '.'));
    }
    CHECK(read_bytes(dir / "out.mp4") == "previous video");
    CHECK(dir.entries() == std::vector<std::string>{"out.mp4"});
}

TEST_CASE("the cancel hook stops write() and finish() with an error, leaving no partial file") {
    for (const VideoFormat format :
         {VideoFormat::mp4, VideoFormat::gif, VideoFormat::png_sequence}) {
        CAPTURE(to_string(format));
        ScratchDirectory dir;
        const auto path = dir / (format == VideoFormat::png_sequence ? "seq" : "out.bin");
        write_bytes(path, "previous");
        if (format == VideoFormat::png_sequence) {
            std::filesystem::remove(path);
            std::filesystem::create_directory(path);
        }
        std::atomic<bool> cancel{false};
        VideoOptions options = small_options(path);
        options.format = format;
        options.cancel = &cancel;
        {
            VideoWriter writer(options);
            writer.write(test_pattern(160, 90, 0));
            writer.write(test_pattern(160, 90, 1));
            cancel = true;
            check_error([&] { writer.write(test_pattern(160, 90, 2)); },
                        collide::ErrorKind::runtime, "interrupted");
            check_error([&] { writer.finish(); }, collide::ErrorKind::runtime, "interrupted");
        }
        CHECK(dir.entries().size() == 1);
        if (format != VideoFormat::png_sequence) CHECK(read_bytes(path) == "previous");
        if (format == VideoFormat::png_sequence) CHECK(std::filesystem::is_empty(path));
    }
}

namespace {

/// Starts the slow-encoding helper, waits until it is encoding, sends `signal_number`,
/// and returns its exit status.
int interrupt_helper_run(const std::filesystem::path& output, int signal_number,
                         const ScratchDirectory& dir) {
    // Wait (up to 20 s, generous for sanitizer builds) for the writer's temporary, then let it
    // encode for a while, so the signal lands in the middle of an encode.
    collide::test::SignalledRun run;
    run.argv = {COLLIDE_VIDEO_INTERRUPT_HELPER, output.string()};
    run.started_child = [&](pid_t child) {
        return collide::test::has_open_file_in(child, dir.path());
    };
    run.start_timeout = std::chrono::seconds(20);
    run.settle = std::chrono::milliseconds(300);
    return collide::test::run_and_signal(run, signal_number);
}

}  // namespace

TEST_CASE("SIGINT and SIGTERM during an encode: exit non-zero, no partial file, old file kept") {
    for (const int signal_number : {SIGINT, SIGTERM}) {
        CAPTURE(signal_number);
        ScratchDirectory dir;
        const auto output = dir / "out.mp4";
        write_bytes(output, "previous video");
        const int status = interrupt_helper_run(output, signal_number, dir);
        REQUIRE(WIFEXITED(status));  // handled, not killed by the signal
        CHECK(WEXITSTATUS(status) == 1);
        CHECK(read_bytes(output) == "previous video");
        CHECK(dir.entries() == std::vector<std::string>{"out.mp4"});
    }
}

TEST_CASE("a full disk is a clear runtime error, not a crash, and leaves no partial file") {
    // A file size limit (RLIMIT_FSIZE) makes writes fail like a full disk (EFBIG instead of
    // ENOSPC) without needing a small filesystem; in a child process, so the limit stays there.
    for (const VideoFormat format :
         {VideoFormat::mp4, VideoFormat::gif, VideoFormat::png_sequence}) {
        CAPTURE(to_string(format));
        ScratchDirectory dir;
        const auto path = dir / (format == VideoFormat::png_sequence ? "seq" : "out.bin");
        write_bytes(dir / "keep.txt", "unrelated");
        const pid_t child = fork();
        REQUIRE(child >= 0);
        if (child == 0) {
            signal(SIGXFSZ, SIG_IGN);        // get EFBIG from write(2) instead of being killed
            const rlimit limit{1024, 1024};  // below one frame of any format
            setrlimit(RLIMIT_FSIZE, &limit);
            int code = 3;  // no error at all
            try {
                VideoOptions options = small_options(path);
                options.format = format;
                options.crf = 0;  // lossless: big packets
                VideoWriter writer(options);
                for (int i = 0; i < 40; ++i) writer.write(test_pattern(160, 90, i));
                writer.finish();
            } catch (const collide::Error& e) {
                const std::string message = e.what();
                code = e.kind() == collide::ErrorKind::runtime &&
                               message.find("File too large") != std::string::npos
                           ? 0
                           : 4;
                if (code != 0) std::fprintf(stderr, "unexpected message: %s\n", e.what());
            } catch (...) {
                code = 5;
            }
            _exit(code);
        }
        int status = 0;
        waitpid(child, &status, 0);
        REQUIRE(WIFEXITED(status));
        CHECK(WEXITSTATUS(status) == 0);
        CHECK(dir.entries() == std::vector<std::string>{"keep.txt"});
    }
}

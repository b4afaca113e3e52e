// The algs4 text format: layout tolerance, content strictness, round trips, the shared files.

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../support/input_error.hpp"
#include "../support/skip.hpp"
#include "collide/error.hpp"
#include "collide/sim/algs4.hpp"

using namespace collide;

namespace {

ParsedScene parse(const std::string& text) {
    std::istringstream in(text);
    return parse_algs4(in, "t.txt");
}

// The message of the Error(input) that parsing `text` throws ("" if none).
std::string parse_error(const std::string& text) {
    try {
        (void)parse(text);
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::input);
        return e.what();
    }
    return "";
}

using collide::test::contains;

}  // namespace

TEST_CASE("algs4: reads every column, in the unit box with walls") {
    const ParsedScene p =
        parse("2\n0.25 0.5 0.01 -0.02 0.05 2.5 10 20 30\n0.75 0.5 0 0 0.05 1 255 0 7\n");
    REQUIRE(p.scene.discs.size() == 2);
    const Disc& d = p.scene.discs[0];
    CHECK(d.position == Vec2{0.25, 0.5});
    CHECK(d.velocity == Vec2{0.01, -0.02});
    CHECK(d.radius == 0.05);
    CHECK(d.mass == 2.5);
    CHECK(d.color == Rgb8{10, 20, 30});
    CHECK(p.scene.discs[1].color == Rgb8{255, 0, 7});
    CHECK(p.scene.box.width == 1.0);
    CHECK(p.scene.box.height == 1.0);
    CHECK(p.scene.box.boundary == Boundary::walls);
    CHECK(p.origin.locate(1).line == 3);
}

TEST_CASE("algs4: untidy layout is accepted (CRLF, blank lines, indentation, no final newline)") {
    const std::string text =
        "\r\n  3\r\n   .5 .5 1.933140129359508E-4 -1.8E+2 .01 1e5 0 0 0\r\n\r\n"
        "\t0.1\t0.1 +0.5 -0.0 0.01 1.0 1 2 3   \n\n0.9 0.9 0 0 0.01 1 4 5 6";
    const ParsedScene p = parse(text);
    REQUIRE(p.scene.discs.size() == 3);
    CHECK(p.scene.discs[0].velocity.x == doctest::Approx(1.933140129359508e-4));
    CHECK(p.scene.discs[0].velocity.y == -180.0);
    CHECK(p.scene.discs[0].mass == 1e5);
    CHECK(p.scene.discs[1].velocity.x == 0.5);
    CHECK(p.scene.discs[2].color == Rgb8{4, 5, 6});
    // lines are counted in the file as written, blank ones included
    CHECK(p.origin.locate(0).line == 3);
    CHECK(p.origin.locate(1).line == 5);
    CHECK(p.origin.locate(2).line == 7);
}

TEST_CASE("algs4: content errors name file, line and field") {
    CHECK(contains(parse_error(""), "t.txt: N: empty file"));
    CHECK(contains(parse_error("two\n"), "t.txt:1: N: expected the number of discs"));
    CHECK(contains(parse_error("-1\n"), "t.txt:1: N"));
    CHECK(contains(parse_error("1 2\n"), "t.txt:1: N"));
    CHECK(contains(parse_error("\x01\xff\xfe binary\n"), "got '??? binary'"));
    CHECK(contains(parse_error("1\n0.5 0.5 0 0 0.1 1 0 0\n"),
                   "t.txt:2: expected 9 columns (rx ry vx vy radius mass r g b), got 8"));
    CHECK(contains(parse_error("1\n0.5 0.5 0 0 0.1 1 0 0 0 0\n"), "got 10"));
    CHECK(contains(parse_error("1\n0.5 0.5 0 0 abc 1 0 0 0\n"),
                   "t.txt:2: radius: 'abc' is not a number"));
    CHECK(contains(parse_error("1\n0.5 0.5 0 0 0.1 1,5 0 0 0\n"),
                   "t.txt:2: mass: '1,5' is not a number"));
    CHECK(
        contains(parse_error("1\n0.5 NaN 0 0 0.1 1 0 0 0\n"), "t.txt:2: ry: not a finite number"));
    CHECK(contains(parse_error("1\n0.5 0.5 inf 0 0.1 1 0 0 0\n"),
                   "t.txt:2: vx: not a finite number"));
    CHECK(contains(parse_error("1\n0.5 0.5 0 0 0.1 1 0 300 0\n"),
                   "t.txt:2: g: colour must be an integer 0..255"));
    CHECK(contains(parse_error("1\n0.5 0.5 0 0 0.1 1 0 0 1.5\n"),
                   "t.txt:2: b: colour must be an integer 0..255"));
    CHECK(contains(parse_error("1\n0.5 0.5 0 0 0.1 1 0 0 -1\n"), "t.txt:2: b"));
    CHECK(contains(parse_error("1\n0.5 0.5 0 0 0.1 +-1 0 0 0\n"), "t.txt:2: mass"));
}

TEST_CASE("algs4: N must agree with the disc lines") {
    CHECK(contains(parse_error("3\n0.5 0.5 0 0 0.1 1 0 0 0\n\n0.2 0.2 0 0 0.1 1 0 0 0\n"),
                   "t.txt:1: N: N = 3 but 2 disc lines follow"));
    CHECK(contains(parse_error("1\n0.5 0.5 0 0 0.1 1 0 0 0\n0.2 0.2 0 0 0.1 1 0 0 0\n"),
                   "t.txt:3: N: more disc lines than N = 1"));
    CHECK(parse("0\n").scene.discs.empty());
}

TEST_CASE("algs4: an absurd N does not allocate before the lines disagree") {
    CHECK(contains(parse_error("1000000000000\n0.5 0.5 0 0 0.1 1 0 0 0\n"),
                   "N = 1000000000000 but 1 disc lines follow"));
    CHECK(contains(parse_error("99999999999999999999999\n"), "t.txt:1: N"));
}

TEST_CASE("algs4: write then read gives the same scene bit for bit") {
    Scene scene;
    scene.discs.push_back({{0.1 + 1e-17, 1.0 / 3.0},
                           {-2.5e-7, 1.933140129359508e-4},
                           0.0123456789012345,
                           13800.0,
                           {1, 2, 3},
                           ""});
    scene.discs.push_back({{0.7, 0.7}, {0.0, -0.0}, 0.2, 1e5, {255, 254, 0}, ""});
    std::stringstream s;
    write_algs4(s, scene);
    const ParsedScene back = parse_algs4(s, "round.txt");
    REQUIRE(back.scene.discs.size() == scene.discs.size());
    for (std::size_t i = 0; i < scene.discs.size(); ++i) {
        CHECK(back.scene.discs[i].position == scene.discs[i].position);
        CHECK(back.scene.discs[i].velocity == scene.discs[i].velocity);
        CHECK(back.scene.discs[i].radius == scene.discs[i].radius);
        CHECK(back.scene.discs[i].mass == scene.discs[i].mass);
        CHECK(back.scene.discs[i].color == scene.discs[i].color);
    }
}

TEST_CASE("algs4: read_algs4_file validates and names the scene after the file") {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / "collide_test_algs4_overlap.txt";
    {
        std::ofstream out(path);
        out << "2\n0.5 0.5 0 0 0.1 1 0 0 0\n0.6 0.5 0 0 0.1 1 0 0 0\n";
    }
    try {
        (void)read_algs4_file(path);
        FAIL("overlapping discs were accepted");
    } catch (const Error& e) {
        const std::string msg = e.what();
        CHECK(contains(msg, ":3: disc 2: overlaps "));
        CHECK(contains(msg, ":2: disc 1"));
    }
    {
        std::ofstream out(path);
        out << "1\n0.5 0.5 0 0 0.1 1 0 0 0\n";
    }
    CHECK(read_algs4_file(path).scene.name == "collide_test_algs4_overlap");
    std::filesystem::remove(path);
    CHECK_THROWS_AS((void)read_algs4_file(path), Error);
}

TEST_CASE("algs4: the course's 25 files load, or are rejected for the right reason") {
    const std::filesystem::path dir = std::filesystem::path(COLLIDE_SHARED_DIR) / "data" / "algs4";
    if (!std::filesystem::is_directory(dir)) {
        COLLIDE_SKIP_TEST(dir << " is absent");
    }
    int loaded = 0;
    int rejected = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() != ".txt" || name == "PROVENANCE.txt") continue;
        CAPTURE(name);
        std::string error;
        try {
            const ParsedScene p = read_algs4_file(entry.path());
            CHECK(!p.scene.discs.empty());
            ++loaded;
        } catch (const Error& e) {
            error = e.what();
            ++rejected;
        }
        if (name == "billiards-overflow.txt") {
            // both discs outside the unit box are named by line
            CHECK(contains(error, "2 discs lie outside the box"));
            CHECK(contains(error, "billiards-overflow.txt:5: disc 4"));
            CHECK(contains(error, "billiards-overflow.txt:6: disc 5"));
        } else if (name == "diffusion3.txt") {
            CHECK(contains(error, "overlaps"));
        } else {
            CHECK(error.empty());
        }
    }
    CHECK(loaded == 23);
    CHECK(rejected == 2);
}

TEST_CASE("algs4: a UTF-8 byte order mark before N is skipped, as in TOML files") {
    const ParsedScene p = parse(
        "\xEF\xBB\xBF"
        "1\n0.5 0.5 0 0 0.1 1 0 0 0\n");
    CHECK(p.scene.discs.size() == 1);
    // Elsewhere the same bytes are still not a number.
    CHECK(parse_error("1\n\xEF\xBB\xBF"
                      "0.5 0.5 0 0 0.1 1 0 0 0\n")
              .find("is not a number") != std::string::npos);
}

TEST_CASE("algs4: a number too small for a double reads as 0, one too large is refused as such") {
    const ParsedScene p = parse("1\n0.5 0.5 1e-400 -1e-400 0.1 1 0 0 0\n");
    CHECK(p.scene.discs[0].velocity.x == 0.0);
    CHECK(p.scene.discs[0].velocity.y == 0.0);
    CHECK(std::signbit(p.scene.discs[0].velocity.y));
    CHECK(parse("1\n0.5 0.5 4.9e-324 0 0.1 1 0 0 0\n").scene.discs[0].velocity.x > 0.0);
    const std::string big = parse_error("1\n0.5 0.5 1e400 0 0.1 1 0 0 0\n");
    CHECK(big.find("t.txt:2: vx: '1e400' is too large for a double") != std::string::npos);
    CHECK(parse_error("1\n0.5 0.5 1e-4x00 0 0.1 1 0 0 0\n").find("is not a number") !=
          std::string::npos);
}

TEST_CASE("algs4: read_algs4_file refuses what is not a regular file") {
    CHECK_THROWS_AS((void)read_algs4_file("/dev/null"), Error);
    CHECK_THROWS_AS((void)read_algs4_file(std::filesystem::temp_directory_path()), Error);
}

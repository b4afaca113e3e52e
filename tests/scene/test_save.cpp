// Writing scenes: TOML and algs4 round trips bit for bit, and safe failures.

#include <doctest/doctest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "../support/input_error.hpp"
#include "../support/temp_dir.hpp"
#include "collide/error.hpp"
#include "collide/scene/load.hpp"
#include "collide/scene/save.hpp"

using namespace collide;

namespace {

void check_same_discs(const Scene& a, const Scene& b) {
    REQUIRE(a.discs.size() == b.discs.size());
    bool same = true;
    for (std::size_t i = 0; i < a.discs.size(); ++i) {
        const Disc& x = a.discs[i];
        const Disc& y = b.discs[i];
        same = same && x.position == y.position && x.velocity == y.velocity &&
               x.radius == y.radius && x.mass == y.mass && x.color == y.color && x.tag == y.tag;
    }
    CHECK(same);
}

std::string save_error(const Scene& scene, const std::filesystem::path& path) {
    return test::input_error_message([&] { save_scene(scene, path); });
}

using collide::test::contains;

}  // namespace

TEST_CASE("save: a generated scene written as TOML reads back bit for bit, hints included") {
    for (const char* name : {"brownian", "tunnelling", "maxwell-boltzmann"}) {
        CAPTURE(name);
        const Scene scene = load_scene(name, COLLIDE_ASSETS_DIR);
        std::ostringstream text;
        write_toml_scene(text, scene);
        const Scene back = parse_toml_scene(text.str(), "back.toml", ".");
        check_same_discs(scene, back);
        CHECK(back.title == scene.title);
        CHECK(back.box.width == scene.box.width);
        CHECK(back.box.boundary == scene.box.boundary);
        CHECK(back.render.trails == scene.render.trails);
        CHECK(back.render.dt == scene.render.dt);
        CHECK(back.render.speed == scene.render.speed);
        CHECK(back.render.color_mode == scene.render.color_mode);
    }
}

TEST_CASE("save: titles and tags with quotes and control characters survive") {
    Scene scene;
    scene.title = "a \"quoted\" \\ title\twith tab";
    Disc d;
    d.position = {0.5, 0.5};
    d.radius = 0.1;
    d.tag = "tr\"acer";
    scene.discs.push_back(d);
    std::ostringstream text;
    write_toml_scene(text, scene);
    const Scene back = parse_toml_scene(text.str(), "back.toml", ".");
    CHECK(back.title == scene.title);
    check_same_discs(scene, back);
}

TEST_CASE("save: the description is exported, and a title that is not UTF-8 still reads back") {
    // Before, every export dropped `description`, and a title taken from a file name in
    // another encoding (bytes that are not UTF-8) made a TOML file `check` refused.
    Scene scene;
    scene.title = "caf\xE9 \xC3\xA9 \xED\xA0\x80 end\xC3";  // Latin-1 e, UTF-8 e, a surrogate
    scene.description = "What it shows: \"quoted\", and \xC3\xA9.";
    Disc d;
    d.position = {0.5, 0.5};
    d.radius = 0.1;
    scene.discs.push_back(d);
    std::ostringstream text;
    write_toml_scene(text, scene);
    const Scene back = parse_toml_scene(text.str(), "back.toml", ".");
    CHECK(back.description == scene.description);
    // Each byte that is not UTF-8 becomes U+FFFD; the rest is kept.
    CHECK(back.title ==
          "caf\xEF\xBF\xBD \xC3\xA9 \xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD end\xEF\xBF\xBD");
    check_same_discs(scene, back);
    // Written again, it is the same file: a fixed point.
    std::ostringstream again;
    write_toml_scene(again, back);
    CHECK(parse_toml_scene(again.str(), "again.toml", ".").title == back.title);
}

TEST_CASE("save: files by extension, through a temporary file, errors leave nothing behind") {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "collide_test_save";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const Scene gas = load_scene("gas", COLLIDE_ASSETS_DIR);
    save_scene(gas, dir / "gas.txt");
    save_scene(gas, dir / "gas.toml");
    check_same_discs(gas, load_scene((dir / "gas.toml").string()));
    const Scene from_txt = load_scene((dir / "gas.txt").string());
    REQUIRE(from_txt.discs.size() == gas.discs.size());
    CHECK(from_txt.discs[3].position == gas.discs[3].position);
    CHECK(!std::filesystem::exists(dir / "gas.toml.partial"));

    CHECK(contains(save_error(gas, dir / "gas.csv"), "cannot write scenes as '.csv'"));
    Scene periodic = gas;
    periodic.box.boundary = Boundary::periodic;
    CHECK(contains(save_error(periodic, dir / "p.txt"), "unit box with walls only"));
    CHECK(!std::filesystem::exists(dir / "p.txt"));
    CHECK(contains(save_error(gas, dir / "missing" / "x.toml"), "does not exist"));
    std::filesystem::remove_all(dir);
}

TEST_CASE("save: an unrelated DEST.partial is neither used nor removed") {
    const test::TempDir dir("save_partial");
    std::ofstream(dir.path / "gas.toml.partial") << "the user's own file";
    save_scene(load_scene("gas", COLLIDE_ASSETS_DIR), dir.path / "gas.toml");
    std::ifstream in(dir.path / "gas.toml.partial");
    const std::string kept((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(kept == "the user's own file");
    CHECK(load_scene((dir.path / "gas.toml").string()).discs.size() > 0);
}

TEST_CASE("save: an interrupt (the cancel flag) writes nothing and keeps the old file") {
    const test::TempDir dir("save_cancel");
    std::ofstream(dir.path / "gas.toml") << "old";
    const std::atomic<bool> cancel{true};
    try {
        save_scene(load_scene("gas", COLLIDE_ASSETS_DIR), dir.path / "gas.toml", &cancel);
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::runtime);
        CHECK(contains(e.what(), "interrupted"));
    }
    std::ifstream in(dir.path / "gas.toml");
    const std::string kept((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(kept == "old");
    CHECK(std::distance(std::filesystem::directory_iterator(dir.path),
                        std::filesystem::directory_iterator()) == 1);
}

TEST_CASE(
    "save: a scene from a file name with byte 0xFF exports and loads back as the same scene") {
    // The title taken from the file name is display text: the loaded scene already holds it as
    // valid UTF-8 (U+FFFD for the 0xFF byte), so load -> export -> load gives the same scene.
    const test::TempDir dir("save_ff");
    const std::filesystem::path toml_file = dir.path / "gas\xFF.toml";
    {
        std::ofstream out(toml_file);
        out << "description = \"two discs\"\n[box]\nwidth = 2\nheight = 1\n"
               "[render]\ntrails = true\nspeed = 0.5\n"
               "[[disc]]\nposition = [0.5, 0.5]\nvelocity = [1, 0]\nradius = 0.1\n"
               "[[disc]]\nposition = [1.5, 0.5]\nvelocity = [-1, 0.25]\nradius = 0.2\n";
    }
    const std::filesystem::path txt_file = dir.path / "box\xFF.txt";
    {
        std::ofstream out(txt_file);
        out << "1\n0.5 0.5 0.1 0 0.05 1 255 0 0\n";
    }
    for (const std::filesystem::path& file : {toml_file, txt_file}) {
        CAPTURE(file.filename().string());
        const Scene scene = load_scene(file.string());
        CHECK(scene.title == file.stem().string().substr(0, 3) + "\xEF\xBF\xBD");
        const std::filesystem::path exported = dir.path / (file.stem().string() + "-export.toml");
        save_scene(scene, exported);
        const Scene back = load_scene(exported.string());
        CHECK(back.title == scene.title);
        CHECK(back.description == scene.description);
        CHECK(back.box.width == scene.box.width);
        CHECK(back.box.height == scene.box.height);
        CHECK(back.render.trails == scene.render.trails);
        CHECK(back.render.speed == scene.render.speed);
        CHECK(back.render.dt == scene.render.dt);
        check_same_discs(scene, back);
    }
}

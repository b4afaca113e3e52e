// Writing scenes: TOML and algs4 round trips bit for bit, and safe failures.

#include <doctest/doctest.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "../support/input_error.hpp"
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
    CHECK(contains(save_error(gas, dir / "missing" / "x.toml"), "cannot write here"));
    std::filesystem::remove_all(dir);
}

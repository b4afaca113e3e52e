// End-to-end: `collide render` / `thumbnail` of 3D scenes (spheres), `check` of the built-in 3D
// scenes, and `--camera`.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "../support/input_error.hpp"
#include "../support/temp_dir.hpp"
#include "collide/image.hpp"
#include "collide/video/png.hpp"
#include "run_collide.hpp"

namespace fs = std::filesystem;
using collide::test::contains;
using collide::test::run_collide;
using collide::test::TempDir;

namespace {

std::string read_bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("collide check: the built-in 3D scenes load and are ok") {
    for (const char* name : {"gas-3d", "alder-wainwright", "spheres-freeze"}) {
        CAPTURE(name);
        const auto r = run_collide(std::string("check ") + name);
        CHECK(r.exit_code == 0);
        CHECK(contains(r.output, std::string("ok: ") + name + ": N = "));
        CHECK(contains(r.output, "spheres (3D)"));
    }
}

TEST_CASE("thumbnail of a 3D scene draws spheres, and the orbit gives the same bytes twice") {
    TempDir dir("render3d");
    const auto thumb = [&](const std::string& name, const std::string& extra) {
        const fs::path out = dir.path / (name + ".png");
        const auto r = run_collide("thumbnail alder-wainwright --size 320x180 --fps 10 --at 0.1 " +
                                   extra + " -o " + out.string());
        CHECK(r.exit_code == 0);
        return out;
    };
    const fs::path fixed = thumb("fixed", "");
    const fs::path orbit_a = thumb("orbit_a", "--camera orbit");
    const fs::path orbit_b = thumb("orbit_b", "--camera orbit");
    REQUIRE(fs::exists(fixed));
    CHECK(read_bytes(orbit_a) == read_bytes(orbit_b));
    CHECK(read_bytes(orbit_a) != read_bytes(fixed));  // the camera has turned by then
    // The spheres are blue (the scene's colour), lit: many pixels are clearly blue.
    const collide::Image image = collide::video::read_png(fixed);
    int blue = 0;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        if (image.rgba[i + 2] > 120 && image.rgba[i + 2] > image.rgba[i] + 60) ++blue;
    }
    CHECK(blue > 2000);
}

TEST_CASE("a bad --camera exits 2 naming the option and the choices") {
    const auto r = run_collide("thumbnail gas-3d --camera spin -o /tmp/collide_never.png");
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "--camera"));
    CHECK(contains(r.output, "fixed or orbit"));
    CHECK_FALSE(fs::exists("/tmp/collide_never.png"));
}

TEST_CASE("a bad --slab exits 2 naming the option") {
    for (const char* value : {"0", "-0.5", "nan"}) {
        CAPTURE(value);
        const auto r = run_collide(std::string("thumbnail gas-3d --slab ") + value +
                                   " -o /tmp/collide_never.png");
        CHECK(r.exit_code == 2);
        CHECK(contains(r.output, "--slab"));
    }
    CHECK_FALSE(fs::exists("/tmp/collide_never.png"));
}

// End-to-end: `collide render` / `thumbnail` of 3D scenes (spheres), `check` of the built-in 3D
// scenes, `--camera` and `--projection`, their golden thumbnails, and OSMesa against EGL.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "../support/input_error.hpp"
#include "../support/skip.hpp"
#include "../support/temp_dir.hpp"
#include "collide/image.hpp"
#include "collide/video/png.hpp"
#include "golden_image.hpp"
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

TEST_CASE("options of the other dimension exit 2 naming the option, as the scene hints do") {
    struct Case {
        const char* args;
        const char* named;
    };
    // The camera of spheres on a 2D scene, valid values all: not ignored.
    for (const Case& c :
         {Case{"thumbnail gas --slab 0.3", "--slab: for 3D scenes only"},
          Case{"render gas --camera orbit", "--camera: for 3D scenes only"},
          Case{"thumbnail billiards --projection perspective", "--projection: for 3D scenes only"},
          Case{"render gas --duration 1 --camera fixed", "--camera: for 3D"},
          // Trails and replays on a 3D scene, either spelling.
          Case{"render gas-3d --trails", "--trails/--no-trails: for 2D scenes"},
          Case{"thumbnail gas-3d --no-trails", "--trails/--no-trails: for 2D"},
          Case{"render gas-3d --replay none", "--replay: for 2D scenes only"}}) {
        CAPTURE(c.args);
        const bool still = std::string(c.args).rfind("thumbnail", 0) == 0;
        const auto r =
            run_collide(std::string(c.args) + " -o /tmp/collide_never" + (still ? ".png" : ".mp4"));
        CHECK(r.exit_code == 2);
        CHECK(contains(r.output, c.named));
    }
    CHECK_FALSE(fs::exists("/tmp/collide_never.mp4"));
    CHECK_FALSE(fs::exists("/tmp/collide_never.png"));
}

TEST_CASE("a bad --projection exits 2 naming the option and the choices") {
    const auto r = run_collide("thumbnail gas-3d --projection fisheye -o /tmp/collide_never.png");
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "--projection"));
    CHECK(contains(r.output, "ortho or perspective"));
    CHECK_FALSE(fs::exists("/tmp/collide_never.png"));
}

TEST_CASE("thumbnail: every built-in 3D scene matches its golden image, and a perspective") {
    TempDir dir("golden3d");
    const std::string list = run_collide("scenes").output;
    struct Golden {
        const char* scene;
        const char* extra;
        const char* name;
    };
    // The 2D goldens' size, rate and time (test_render_cli.cpp).
    for (const Golden& g :
         {Golden{"gas-3d", "", "gas-3d"}, Golden{"alder-wainwright", "", "alder-wainwright"},
          Golden{"spheres-freeze", "", "spheres-freeze"},
          Golden{"alder-wainwright", " --projection perspective",
                 "alder-wainwright-perspective"}}) {
        CAPTURE(g.name);
        CHECK(contains(list, g.scene));
        const fs::path out = dir.path / (std::string(g.name) + ".png");
        const auto r =
            run_collide(std::string("thumbnail ") + g.scene + " --size 320x180 --fps 10 --at 0.05" +
                        g.extra + " -o " + out.string());
        REQUIRE_MESSAGE(r.exit_code == 0, r.output);
        collide::test::check_golden(out, g.name);
    }
}

TEST_CASE("thumbnail --gl: OSMesa and EGL surfaceless give the same 3D still, both projections") {
    TempDir dir("gl3d");
    for (const char* projection : {"ortho", "perspective"}) {
        CAPTURE(projection);
        const std::string still = std::string(
                                      "thumbnail alder-wainwright --size 320x180 --at 0.5 "
                                      "--camera orbit --projection ") +
                                  projection;
        const fs::path o = dir.path / (std::string(projection) + "_o.png");
        const fs::path e = dir.path / (std::string(projection) + "_e.png");
        const auto osmesa = run_collide(still + " --gl osmesa -o " + o.string());
        const auto egl = run_collide(still + " --gl egl -o " + e.string());
        if (contains(osmesa.output, "built without it") || contains(egl.output, "built without it"))
            COLLIDE_SKIP_TEST("this build lacks OSMesa or EGL");
        if (egl.exit_code != 0 && contains(egl.output, "EGL"))
            COLLIDE_SKIP_TEST("EGL cannot render here: " << egl.output);
        REQUIRE_MESSAGE(osmesa.exit_code == 0, osmesa.output);
        REQUIRE_MESSAGE(egl.exit_code == 0, egl.output);
        CHECK(read_bytes(o).size() > 1000);
        CHECK(read_bytes(o) == read_bytes(e));
    }
}

TEST_CASE("[render] camera, projection and slab of a 3D scene: hints the options override") {
    TempDir dir("hints3d");
    // One title for both files: a 320x180 thumbnail draws it (else taken from the file's name).
    const std::string spheres =
        "title = \"Spheres\"\ndimension = 3\n[box]\nboundary = \"periodic\"\n[[fcc]]\ncells = "
        "3\npacking_fraction = "
        "0.3\nseed = 2\n";
    const auto write = [&](const std::string& name, const std::string& text) {
        const fs::path p = dir.path / name;
        std::ofstream(p) << text;
        return p.string();
    };
    const std::string plain = write("plain.toml", spheres);
    const std::string hinted =
        write("hinted.toml",
              spheres + "[render]\ncamera = \"orbit\"\nprojection = \"perspective\"\nslab = 0.5\n");
    const auto thumb = [&](const std::string& scene, const std::string& extra,
                           const std::string& name) {
        const fs::path out = dir.path / (name + ".png");
        const auto r = run_collide("thumbnail " + scene + " --size 320x180 --at 1 " + extra +
                                   " -o " + out.string());
        REQUIRE_MESSAGE(r.exit_code == 0, r.output);
        return read_bytes(out);
    };
    const std::string by_options =
        thumb(plain, "--camera orbit --projection perspective --slab 0.5", "options");
    CHECK(thumb(hinted, "", "hints") == by_options);
    CHECK(thumb(hinted, "--camera fixed --projection ortho --slab 100", "overridden") ==
          thumb(plain, "", "plain"));
    CHECK(thumb(plain, "", "plain2") != by_options);
}

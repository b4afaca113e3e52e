// End-to-end: `collide check` on good and bad scenes (exit codes 0/2 and the messages).

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../support/input_error.hpp"
#include "../support/skip.hpp"
#include "run_collide.hpp"

using collide::test::run_collide;
using collide::test::shell_quoted;

namespace {

using collide::test::contains;

// Writes `text` to a temporary file and returns its path (quoted for the shell).
std::string temp_scene(const std::string& name, const std::string& text) {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("collide_e2e_" + name);
    std::ofstream(path) << text;
    return shell_quoted(path.string());
}

}  // namespace

TEST_CASE("collide check: a good algs4 file gives exit 0 and a one-line summary") {
    const auto r = run_collide(
        "check " +
        temp_scene("good.txt", "2\n0.25 0.5 0.1 0 0.05 1 0 0 0\n0.75 0.5 0 0 0.05 1 0 0 0\n"));
    CHECK(r.exit_code == 0);
    CHECK(contains(r.output, "ok: "));
    CHECK(contains(r.output, "N = 2, eta = 0.0157"));
    CHECK(contains(r.output, "walls 1 x 1"));
    CHECK(contains(r.output, "E = 0.005"));
}

TEST_CASE("collide check: a built-in scene by name") {
    const auto r = run_collide("check tunnelling");
    CHECK(r.exit_code == 0);
    CHECK(contains(r.output, "ok: tunnelling: N = "));
}

TEST_CASE("collide check: bad scenes exit 2 naming file, line and reason") {
    auto r =
        run_collide("check " + temp_scene("overlap.txt",
                                          "2\n0.5 0.5 0 0 0.1 1 0 0 0\n0.6 0.5 0 0 0.1 1 0 0 0\n"));
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "collide: error: "));
    CHECK(contains(r.output, "overlap.txt:3: disc 2: overlaps "));

    r = run_collide("check " + temp_scene("columns.txt", "1\n0.5 0.5 0 0 0.1 1 0 0\n"));
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "columns.txt:2: expected 9 columns"));

    r = run_collide("check " +
                    temp_scene("typo.toml", "[[disc]]\nposition = [0.5, 0.5]\nradus = 0.1\n"));
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "typo.toml:3: disc[0]: unknown key 'radus' (did you mean 'radius'?)"));

    r = run_collide(
        "check " +
        temp_scene("dense.toml", "[[generate]]\npacking_fraction = 0.95\nradius = 0.01\n"));
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output,
                   "dense.toml:2: generate[0].packing_fraction: 0.95 is above the maximum"));

    r = run_collide("check no-such-scene");
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "'no-such-scene': not a scene file and not a built-in scene"));
}

TEST_CASE("collide check: the course's billiards-overflow.txt is rejected, naming each line") {
    const std::filesystem::path file =
        std::filesystem::path(COLLIDE_SHARED_DIR) / "data/algs4/billiards-overflow.txt";
    if (!std::filesystem::exists(file)) {
        COLLIDE_SKIP_TEST(file << " is absent");
    }
    const auto r = run_collide("check '" + file.string() + "'");
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "billiards-overflow.txt:5: disc 4"));
    CHECK(contains(r.output, "billiards-overflow.txt:6: disc 5"));
}

// Issue 15: these scenes passed check, then every event-driven run collided forever at t = 0.
TEST_CASE("collide check: discs wedged wall to wall and moving along the row are refused") {
    const std::string rack = temp_scene("wedged.txt",
                                        "3\n"
                                        "0.16666666666666666 0.5 0 0 0.16666666666666666 1 0 0 0\n"
                                        "0.5 0.5 0.25 0 0.16666666666666666 1 0 0 0\n"
                                        "0.8333333333333334 0.5 0 0 0.16666666666666666 1 0 0 0\n");
    auto r = run_collide("check " + rack);
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "wedged.txt:3: disc 2 velocity: moves along x (0.25)"));
    CHECK(contains(r.output, "straight row of 3 touching discs"));
    r = run_collide("simulate " + rack + " --until 1");
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "wedged.txt:3: disc 2 velocity"));

    r = run_collide("check " + temp_scene("wide.txt", "1\n0.5 0.5 1 0 0.5 1 0 0 0\n"));
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output,
                   "wide.txt:2: disc 1 velocity: moves along x (1), but the disc is as "
                   "wide as the box"));
}

TEST_CASE("collide check: a missing argument is a usage error") {
    const auto r = run_collide("check");
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "scene is required"));
}

TEST_CASE("collide check --export freezes a generated scene that checks the same") {
    const std::filesystem::path out =
        std::filesystem::temp_directory_path() / "collide_e2e_export.toml";
    std::filesystem::remove(out);
    const auto first = run_collide("check brownian --export '" + out.string() + "'");
    CHECK(first.exit_code == 0);
    CHECK(contains(first.output, "wrote "));
    const auto again = run_collide("check '" + out.string() + "'");
    CHECK(again.exit_code == 0);
    // same N, eta, boundary and energy in the one-line summary
    const auto summary = [](const std::string& s) {
        return s.substr(s.find("N = "), s.find('\n', s.find("N = ")) - s.find("N = "));
    };
    CHECK(summary(first.output) == summary(again.output));
    std::filesystem::remove(out);

    const auto bad = run_collide("check gas --export /nonexistent-dir/x.toml");
    CHECK(bad.exit_code == 2);
    CHECK(contains(bad.output, "'/nonexistent-dir' does not exist"));
}

TEST_CASE("collide check: a 3D scene (dimension = 3) gives a summary of its spheres") {
    const auto r = run_collide("check " + temp_scene("fcc.toml", R"(dimension = 3
[box]
boundary = "periodic"
[[fcc]]
cells = 3
packing_fraction = 0.3
)"));
    CHECK(r.exit_code == 0);
    CHECK(contains(r.output, "N = 108 spheres (3D), eta = 0.3, box 1 x 1 x 1, periodic, kT = 1"));
    CHECK(contains(r.output, "collisions per time unit"));
}

TEST_CASE("collide check: a 3D row from wall to wall may move across itself, not along") {
    const auto r = run_collide("check " + temp_scene("across3.toml", R"(dimension = 3
[[sphere]]
position = [0.5, 0.25, 0.5]
radius = 0.25
velocity = [0.5, 0, -0.2]
[[sphere]]
position = [0.5, 0.75, 0.5]
radius = 0.25
velocity = [-0.5, 0, 0.3]
)"));
    CHECK(r.exit_code == 0);
    CHECK(contains(r.output, "N = 2 spheres (3D)"));
}

TEST_CASE("collide check: a 3D [[generate]] region is a box inside the box") {
    const auto r = run_collide("check " + temp_scene("region.toml", R"(dimension = 3
[box]
depth = 2
[[generate]]
packing_fraction = 0.2
radius = 0.05
region = [[0, 0, 1], [1, 1, 2]]
)"));
    CHECK(r.exit_code == 0);
    CHECK(contains(r.output, "N = 382 spheres (3D), eta = 0.1"));
}

TEST_CASE("collide check: bad 3D scenes exit 2 naming file, line and field") {
    struct Case {
        const char* file;
        const char* text;
        const char* message;
    };
    const Case cases[] = {
        {"overlap3.toml",
         "dimension = 3\n[[sphere]]\nposition = [0.5, 0.5, 0.5]\nradius = 0.1\n"
         "[[sphere]]\nposition = [0.5, 0.55, 0.5]\nradius = 0.1\n",
         "overlap3.toml:6: sphere[1].position: overlaps sphere[0]"},
        {"outside3.toml",
         "dimension = 3\n[box]\ndepth = 0.5\n[[sphere]]\nposition = [0.5, 0.5, 0.45]\n"
         "radius = 0.1\n",
         "outside3.toml:5: sphere[0].position: the sphere (radius 0.1) is not inside the box"},
        {"depth2.toml", "[box]\nwidth = 1\ndepth = 1\n",
         "depth2.toml:3: box.depth: a 3D key in a 2D scene"},
        {"sphere2.toml", "[[sphere]]\nposition = [0.5, 0.5, 0.5]\nradius = 0.1\n",
         "sphere2.toml:1: sphere: a 3D key in a 2D scene"},
        {"disc3.toml", "dimension = 3\n[[disc]]\nposition = [0.5, 0.5]\nradius = 0.1\n",
         "disc3.toml:2: disc: a 2D key in a 3D scene"},
        {"dense3.toml",
         "dimension = 3\n[box]\nboundary = \"periodic\"\n[[generate]]\npacking_fraction = 0.45\n"
         "radius = 0.05\n",
         "dense3.toml:5: generate[0].packing_fraction: packing 0.449771 is too dense to generate"},
        {"fcc3.toml",
         "dimension = 3\n[box]\ndepth = 0.1\nboundary = \"periodic\"\n[[fcc]]\ncells = 4\n"
         "packing_fraction = 0.5\n",
         "fcc3.toml:7: fcc.packing_fraction: packing 0.5 is too dense to generate in this box"},
        // A generator's error names the line of the field it blames, not the block's header.
        {"cells3.toml", "dimension = 3\n[[fcc]]\npacking_fraction = 0.3\ncells = [2, 2, 2000]\n",
         "cells3.toml:4: fcc.cells: each count of unit cells must be from 1 to 1000"},
        {"radius3.toml",
         "dimension = 3\n\n[[generate]]\ncount = 1\nregion = [[0, 0, 0], [1, 1, 0.1]]\n"
         "\nradius = 0.06\n",
         "radius3.toml:7: generate[0].radius"},
        {"dim4.toml", "dimension = 4\n", "dim4.toml:1: dimension: expected 2 (discs) or 3"},
        {"wide3.toml",
         "dimension = 3\n[box]\ndepth = 0.2\n[[sphere]]\nposition = [0.5, 0.5, 0.1]\n"
         "radius = 0.1\nvelocity = [0.3, 0, 0.5]\n",
         "wide3.toml:7: sphere[0].velocity: jammed: it is as wide as the box along z"},
        {"row3.toml",
         "dimension = 3\n[[sphere]]\nposition = [0.5, 0.25, 0.5]\nradius = 0.25\n"
         "[[sphere]]\nposition = [0.5, 0.75, 0.5]\nradius = 0.25\nvelocity = [0, 1, 0]\n",
         "row3.toml:8: sphere[1].velocity: jammed: it is wedged between the walls y = 0 and y = 1 "
         "in a straight row of 2 touching spheres"},
        {"region3.toml",
         "dimension = 3\n[[generate]]\ncount = 10\nradius = 0.05\n"
         "region = [[0, 0, 0], [1, 1, 2]]\n",
         "region3.toml:5: generate[0].region: the region must lie inside the box"},
        {"region2d3.toml",
         "dimension = 3\n[[generate]]\ncount = 10\nradius = 0.05\nregion = [[0, 0], [1, 1]]\n",
         "region2d3.toml:5: generate[0].region[0]: expected [x, y, z]"},
        // [render]: the camera of spheres in a 2D scene, trails or replays in a 3D one, and bad
        // camera values.
        {"camera2.toml", "[box]\nwidth = 1\n[render]\nduration = 5\ncamera = \"orbit\"\n",
         "camera2.toml:5: render.camera: a 3D key in a 2D scene"},
        {"projection2.toml", "[render]\nprojection = \"perspective\"\n",
         "projection2.toml:2: render.projection: a 3D key in a 2D scene"},
        {"slab2.toml", "[render]\nslab = 0.3\n",
         "slab2.toml:2: render.slab: a 3D key in a 2D scene"},
        {"trails3.toml",
         "dimension = 3\n[[sphere]]\nposition = [0.5, 0.5, 0.5]\nradius = 0.1\n[render]\n"
         "trails = true\n",
         "trails3.toml:6: render.trails: a 2D key in a 3D scene"},
        {"replay3.toml",
         "dimension = 3\n[render]\nreplay = \"all\"\n[[sphere]]\nposition = [0.5, 0.5, 0.5]\n"
         "radius = 0.1\n",
         "replay3.toml:3: render.replay: a 2D key in a 3D scene"},
        {"projection3.toml",
         "dimension = 3\n[[sphere]]\nposition = [0.5, 0.5, 0.5]\nradius = 0.1\n[render]\n"
         "projection = \"fisheye\"\n",
         "projection3.toml:6: render.projection: expected one of ortho, perspective (got "
         "\"fisheye\")"},
        {"camera3.toml",
         "dimension = 3\n[[sphere]]\nposition = [0.5, 0.5, 0.5]\nradius = 0.1\n[render]\n"
         "camera = 3\n",
         "camera3.toml:6: render.camera:"},
        {"slab3.toml",
         "dimension = 3\n[[sphere]]\nposition = [0.5, 0.5, 0.5]\nradius = 0.1\n[render]\n"
         "slab = -1\n",
         "slab3.toml:6: render.slab:"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.file);
        const auto r = run_collide("check " + temp_scene(c.file, c.text));
        CHECK(r.exit_code == 2);
        CHECK(contains(r.output, c.message));
    }
}

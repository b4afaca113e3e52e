// Pause and ponder (issue #45) end to end: the built-in scenes that ask hold a question, frozen
// at least 2 s, then its reveal (`--timeline-json`); the question is in the subtitles and the
// slide player's page; `--questions none` and `--mode time` ask nothing; bad questions in a scene
// file exit 2 naming file, line and field.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "../support/files.hpp"
#include "../support/temp_dir.hpp"
#include "run_collide.hpp"

namespace fs = std::filesystem;
using collide::test::run_collide;
using collide::test::TempDir;

namespace {

nlohmann::json read_json(const fs::path& path) {
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

/// The question segments of a timeline, each checked: frozen at least 2 s, then its reveal on
/// the same state, then the run.
int checked_questions(const nlohmann::json& timeline) {
    const nlohmann::json& segments = timeline["segments"];
    int questions = 0;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const nlohmann::json& q = segments[i];
        if (q["kind"] != "question") continue;
        ++questions;
        CAPTURE(q.dump());
        CHECK(q["moves"] == false);
        CHECK(q["end"].get<double>() - q["start"].get<double>() >= 2.0 - 1e-9);
        CHECK(q["sim_start"] == q["sim_end"]);
        CHECK_FALSE(q["caption"].get<std::string>().empty());
        REQUIRE(i + 1 < segments.size());
        const nlohmann::json& reveal = segments[i + 1];
        CHECK(reveal["kind"] == "reveal");
        CHECK(reveal["moves"] == false);
        CHECK(reveal["sim_start"] == q["sim_start"]);
        CHECK(reveal["caption"].get<std::string>().rfind("Answer: ", 0) == 0);
        REQUIRE(i + 2 < segments.size());
        CHECK(segments[i + 2]["moves"] == true);  // the run goes on
    }
    return questions;
}

std::string render_args(const std::string& scene, const fs::path& dir) {
    return "render " + scene + " --size 320x180 --fps 10 --progress none -o " +
           (dir / (scene + ".mp4")).string() + " --timeline-json " + (dir / "t.json").string() +
           " ";
}

}  // namespace

TEST_CASE("gas, billiards and tunnelling ask: a frozen question, then its reveal") {
    for (const std::string scene : {"gas", "billiards", "tunnelling"}) {
        CAPTURE(scene);
        TempDir dir("questions");
        const fs::path vtt = dir.path / "s.vtt";
        const auto r =
            run_collide(render_args(scene, dir.path) + "--subtitles-file " + vtt.string());
        REQUIRE_MESSAGE(r.exit_code == 0, r.output);
        // Asked where the scene says: no notice of a question moved or left out.
        CHECK_MESSAGE(r.output.find("render.questions") == std::string::npos, r.output);
        const nlohmann::json timeline = read_json(dir.path / "t.json");
        CHECK(checked_questions(timeline) >= 1);
        const std::string subtitles = collide::test::read_all(vtt);
        CHECK(subtitles.find("Pause and think: ") != std::string::npos);
        CHECK(subtitles.find("Answer: ") != std::string::npos);

        const auto none = run_collide(render_args(scene, dir.path) + "--questions none");
        REQUIRE_MESSAGE(none.exit_code == 0, none.output);
        CHECK(checked_questions(read_json(dir.path / "t.json")) == 0);
    }
}

TEST_CASE("the slide player's page carries the question and its answer as chapters") {
    TempDir dir("questions-slides");
    const fs::path slides = dir.path / "talk";
    const auto r = run_collide(render_args("billiards", dir.path) + "--slides " + slides.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    const std::string page = collide::test::read_all(slides / "index.html");
    CHECK(page.find("Pause and think: which collides first") != std::string::npos);
    CHECK(page.find("Answer: ") != std::string::npos);
}

TEST_CASE("--mode time asks nothing the event-driven panel would answer, and says so") {
    TempDir dir("questions-mode");
    const auto r = run_collide(render_args("gas", dir.path) + "--mode time");
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    CHECK(checked_questions(read_json(dir.path / "t.json")) == 0);
    CHECK_MESSAGE(r.output.find("needs the event-driven panel") != std::string::npos, r.output);
    const auto event = run_collide(render_args("gas", dir.path) + "--mode event");
    REQUIRE_MESSAGE(event.exit_code == 0, event.output);
    CHECK(checked_questions(read_json(dir.path / "t.json")) >= 1);
}

TEST_CASE("bad questions: --questions and [[render.questions]] exit 2 naming what is wrong") {
    TempDir dir("questions-bad");
    const fs::path mp4 = dir.path / "x.mp4";
    const auto option =
        run_collide("render gas --questions some --progress none -o " + mp4.string());
    CHECK(option.exit_code == 2);
    CHECK_MESSAGE(option.output.find("--questions") != std::string::npos, option.output);
    const fs::path scene = dir.path / "q.toml";
    const std::string head =
        "[box]\nwidth = 1.0\nheight = 1.0\n"
        "[[disc]]\nposition = [0.3, 0.5]\nvelocity = [0.1, 0]\nradius = 0.05\n"
        "[render]\nduration = 10\n[[render.questions]]\nat = 3\n";
    const struct {
        std::string rest;
        std::string says;
    } cases[] = {
        {"kind = \"which\"\n", "q.toml:12: render.questions[0].kind: expected one of"},
        {"kind = \"how-many\"\nthink = 1\n", "render.questions[0].think"},
        {"", "render.questions[0].kind: missing"},
        {"kind = \"how-many\"\nhold = 2\n", "render.questions[0]"},
    };
    for (const auto& c : cases) {
        std::ofstream(scene) << head << c.rest;
        for (const std::string& command :
             {"render " + scene.string() + " --progress none -o " + mp4.string(),
              "check " + scene.string()}) {
            const auto bad = run_collide(command);
            CAPTURE(command);
            CAPTURE(c.rest);
            CHECK(bad.exit_code == 2);
            CHECK_MESSAGE(bad.output.find(c.says) != std::string::npos, bad.output);
        }
    }
    CHECK(!fs::exists(mp4));
}

TEST_CASE(
    "a question with nothing to ask is refused naming its field, or left out with --duration") {
    TempDir dir("questions-quiet");
    const fs::path scene = dir.path / "q.toml";
    // One disc alone in a periodic box: it never collides.
    std::ofstream(scene) << "[box]\nwidth = 1.0\nheight = 1.0\nboundary = \"periodic\"\n"
                            "[[disc]]\nposition = [0.3, 0.5]\nvelocity = [0.1, 0]\nradius = 0.05\n"
                            "[render]\nduration = 20\n"
                            "[[render.questions]]\nat = 3\nkind = \"next-collision\"\n";
    const std::string args =
        "render " + scene.string() + " --size 320x180 --fps 10 --progress none -o " +
        (dir.path / "q.mp4").string() + " --timeline-json " + (dir.path / "t.json").string();
    const auto refused = run_collide(args);
    CHECK(refused.exit_code == 2);
    CHECK_MESSAGE(refused.output.find("q.toml:12: render.questions.at: nothing to ask at 3 s") !=
                      std::string::npos,
                  refused.output);
    CHECK_FALSE(fs::exists(dir.path / "q.mp4"));
    CHECK_FALSE(fs::exists(dir.path / "t.json"));
    // The video's length given on the command line: left out, as a caption past its end.
    const auto cut = run_collide(args + " --duration 20");
    REQUIRE_MESSAGE(cut.exit_code == 0, cut.output);
    CHECK_MESSAGE(cut.output.find("q.toml:12: render.questions.at: nothing to ask at 3 s") !=
                      std::string::npos,
                  cut.output);
    CHECK(checked_questions(read_json(dir.path / "t.json")) == 0);
}

namespace {

/// The will-see questions of a timeline: their question segments' captions ask it.
int will_see_questions(const nlohmann::json& timeline) {
    int out = 0;
    const nlohmann::json& segments = timeline["segments"];
    for (std::size_t i = 0; i + 1 < segments.size(); ++i) {
        const nlohmann::json& q = segments[i];
        if (q["kind"] != "question" ||
            q["caption"].get<std::string>().find("will the next check see") == std::string::npos)
            continue;
        ++out;
        // The reveal is the replay of the failed step: as long as a replay.
        const nlohmann::json& reveal = segments[i + 1];
        CHECK(reveal["end"].get<double>() - reveal["start"].get<double>() >= 6.0 - 1e-9);
        CHECK(reveal["caption"].get<std::string>().rfind("Answer: no", 0) == 0);
    }
    return out;
}

}  // namespace

TEST_CASE("tunnelling asks whether the next check sees it: --mode time asks, --mode event not") {
    TempDir dir("questions-will-see");
    const fs::path vtt = dir.path / "s.vtt";
    const auto both =
        run_collide(render_args("tunnelling", dir.path) + "--subtitles-file " + vtt.string());
    REQUIRE_MESSAGE(both.exit_code == 0, both.output);
    CHECK_MESSAGE(both.output.find("render.questions") == std::string::npos, both.output);
    const nlohmann::json timeline = read_json(dir.path / "t.json");
    CHECK(checked_questions(timeline) >= 2);
    CHECK(will_see_questions(timeline) == 1);
    CHECK(collide::test::read_all(vtt).find("will the next check see") != std::string::npos);

    const auto time = run_collide(render_args("tunnelling", dir.path) + "--mode time");
    REQUIRE_MESSAGE(time.exit_code == 0, time.output);
    CHECK_MESSAGE(time.output.find("moved from") == std::string::npos, time.output);
    const nlohmann::json time_line = read_json(dir.path / "t.json");
    CHECK(will_see_questions(time_line) == 1);
    CHECK(checked_questions(time_line) == 1);  // only the time-driven panel's question

    const auto event = run_collide(render_args("tunnelling", dir.path) + "--mode event");
    REQUIRE_MESSAGE(event.exit_code == 0, event.output);
    CHECK(will_see_questions(read_json(dir.path / "t.json")) == 0);
    CHECK_MESSAGE(event.output.find("needs the time-driven panel") != std::string::npos,
                  event.output);
}

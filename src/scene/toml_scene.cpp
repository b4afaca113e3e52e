// TOML scenes: walk the document table by table, refuse unknown keys (with a suggestion), turn
// each value into the scene's types with file:line in every message, then validate the whole.

#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <utility>
#include <vector>

#include "collide/error.hpp"
#include "collide/named_values.hpp"
#include "collide/render_options.hpp"
#include "collide/scene/load.hpp"
#include "collide/sim/algs4.hpp"
#include "collide/sim/generate.hpp"
#include "collide/sim/generate3.hpp"
#include "collide/sim/scene_check.hpp"
#include "collide/space.hpp"
#include "toml_limits.hpp"
#include "toml_text.hpp"
#include "toml_values.hpp"

namespace collide {

namespace {

using namespace toml_text::keys;  // the keys each table accepts
using toml_text::clipped;
using toml_text::joined;
using toml_text::num;

class TomlReader : private toml_text::ValueReader {
  public:
    TomlReader(std::string file, std::filesystem::path base_dir,
               std::optional<std::uint64_t> seed_override)
        : ValueReader(std::move(file)),
          base_dir_(std::move(base_dir)),
          seed_override_(seed_override) {}

    /// A scene of either dimension (`dimension = 3`: spheres).
    AnyScene read_any(std::string_view text) {
        toml::table doc = parse(text);
        check_keys(doc, "", top_keys);
        if (dimension(doc) == 3) return read3(doc);
        return read2(doc);
    }

    Scene read(std::string_view text) {
        toml::table doc = parse(text);
        check_keys(doc, "", top_keys);
        if (dimension(doc) == 3) {
            fail(*doc.get("dimension"), "dimension",
                 "a 3D scene (spheres): `collide check`, `simulate`, `render` and `thumbnail` "
                 "read it; this reader takes discs only");
        }
        return read2(doc);
    }

  private:
    int dimension(const toml::table& doc) const {
        const toml::node* n = doc.get("dimension");
        if (n == nullptr) return 2;
        const std::int64_t d = integer(*n, "dimension", 2);
        if (d != 2 && d != 3) fail(*n, "dimension", "expected 2 (discs) or 3 (spheres)");
        return static_cast<int>(d);
    }

    // A key that only a 3D scene has, in a 2D one (or the reverse): named where it is written.
    void refuse_other_dimension(const toml::table& doc, int dim) const {
        const Keys keys3 = {"sphere", "fcc"};
        const Keys keys2 = {"disc", "include"};
        for (const std::string& key : dim == 2 ? keys3 : keys2) {
            if (const toml::node* n = doc.get(key)) {
                fail(*n, key,
                     dim == 2 ? "a 3D key in a 2D scene (add dimension = 3 for spheres)"
                              : "a 2D key in a 3D scene (dimension = 3 has [[sphere]], [[fcc]] "
                                "and [[generate]])");
            }
        }
        if (const toml::node* render = doc.get("render"); render != nullptr && render->is_table()) {
            for (const std::string& key : dim == 2 ? render_keys3 : render_keys2) {
                const toml::node* n = render->as_table()->get(key);
                if (n == nullptr) continue;
                fail(*n, "render." + key,
                     dim == 2 ? "a 3D key in a 2D scene (the camera of spheres: add "
                                "dimension = 3)"
                              : "a 2D key in a 3D scene (spheres are drawn without trails and "
                                "their failures are not replayed yet)");
            }
        }
        if (const toml::node* box = doc.get("box"); box != nullptr && box->is_table() && dim == 2) {
            if (const toml::node* depth = box->as_table()->get("depth"))
                fail(*depth, "box.depth",
                     "a 3D key in a 2D scene (add dimension = 3 for a box with a depth)");
        }
    }

    Scene read2(const toml::table& doc) {
        refuse_other_dimension(doc, 2);
        if (const toml::node* n = doc.get("title"))
            scene_.title = bounded_text(*n, "title", max_title_chars);
        if (const toml::node* n = doc.get("description"))
            scene_.description = bounded_text(*n, "description", max_description_chars);
        if (const toml::node* n = doc.get("box")) read_box(*n, scene_.box);
        if (const toml::node* n = doc.get("render")) read_render(*n);
        if (const toml::node* n = doc.get("include")) read_includes(*n);
        if (const toml::node* n = doc.get("disc")) read_discs(*n);
        // Periodic boxes accept any position: keep them in the box, as the engines expect.
        for (Disc& d : scene_.discs) d.position = scene_.box.wrap(d.position);
        if (const toml::node* n = doc.get("generate")) {
            // The generators build grids from the discs already there: those must be sane.
            validate_scene(scene_, origin_);
            read_generators(*n);
        }
        if (speed_colored_ && !scene_.render.color_mode)
            scene_.render.color_mode = ColorMode::speed;
        validate_scene(scene_, origin_);
        check_replay_tag();
        return std::move(scene_);
    }

    // ---------------------------------------------------------------------------------------
    // 3D: spheres in a box with a depth.

    SphereScene read3(const toml::table& doc) {
        refuse_other_dimension(doc, 3);
        SphereScene s;
        if (const toml::node* n = doc.get("title"))
            s.title = bounded_text(*n, "title", max_title_chars);
        if (const toml::node* n = doc.get("description"))
            s.description = bounded_text(*n, "description", max_description_chars);
        if (const toml::node* n = doc.get("box")) read_box(*n, s.box);
        if (const toml::node* n = doc.get("render")) read_render(*n);
        if (const toml::node* n = doc.get("sphere")) read_spheres(*n, s);
        if (const toml::node* n = doc.get("fcc")) read_fcc(*n, s);
        if (const toml::node* n = doc.get("generate")) read_sphere_generators(*n, s);
        if (s.spheres.empty()) {
            throw_scene_error(file_, 0, "sphere",
                              "a 3D scene needs spheres: [[sphere]], [[fcc]] or [[generate]]");
        }
        s.render = std::move(scene_.render);
        if (speed_colored_ && !s.render.color_mode) s.render.color_mode = ColorMode::speed;
        return s;
    }

    Vec3 triple(const toml::node& n, const std::string& field) const {
        const toml::array* a = n.as_array();
        if (a == nullptr || a->size() != 3) fail(n, field, "expected [x, y, z]");
        return {number(*a->get(0), field + "[0]"), number(*a->get(1), field + "[1]"),
                number(*a->get(2), field + "[2]")};
    }

    // Explicit spheres: each inside a walled box, none overlapping another (named at the later
    // one's line). O(n^2) over the explicit spheres, which a file lists by hand.
    void read_spheres(const toml::node& n, SphereScene& s) const {
        const toml::array* a = n.as_array();
        if (a == nullptr) fail(n, "sphere", "expected [[sphere]] tables");
        constexpr std::size_t most_explicit = 100'000;
        if (a->size() > most_explicit)
            fail(n, "sphere",
                 "more than " + std::to_string(most_explicit) +
                     " explicit spheres: use [[fcc]] or [[generate]]");
        std::vector<std::pair<std::size_t, std::size_t>> contacts;  // touching pairs (j < i)
        std::vector<const toml::node*> velocity_at;  // per sphere, null without a velocity
        for (std::size_t i = 0; i < a->size(); ++i) {
            const std::string field = "sphere[" + std::to_string(i) + "]";
            const toml::table& t = table_at(*a->get(i), field);
            check_keys(t, field, sphere_keys);
            Sphere p;
            const toml::node& at = required(t, "position", field);
            p.position = triple(at, field + ".position");
            if (const toml::node* v = t.get("velocity"))
                p.velocity = triple(*v, field + ".velocity");
            p.radius = positive(required(t, "radius", field), field + ".radius");
            if (const toml::node* v = t.get("mass")) p.mass = positive(*v, field + ".mass");
            if (const toml::node* v = t.get("color")) p.color = rgb(*v, field + ".color");
            if (const toml::node* v = t.get("tag")) p.tag = text_value(*v, field + ".tag");
            if (!s.box.contains(p.position, p.radius))
                fail(at, field + ".position",
                     "the sphere (radius " + num(p.radius) + ") is not inside the box [0, " +
                         num(s.box.width) + "] x [0, " + num(s.box.height) + "] x [0, " +
                         num(s.box.depth) + "]");
            p.position = s.box.wrap(p.position);
            for (std::size_t j = 0; j < s.spheres.size(); ++j) {
                const Sphere& o = s.spheres[j];
                const double dist = norm(s.box.displacement(o.position, p.position));
                const double sigma = p.radius + o.radius;
                // Touching within 1e-9 of the contact distance is allowed, as for discs.
                if (dist < sigma * (1.0 - contact_tolerance))
                    fail(at, field + ".position",
                         "overlaps sphere[" + std::to_string(j) + "] (centres " + num(dist) +
                             " apart, radii add up to " + num(sigma) + ")");
                if (dist <= sigma * (1.0 + contact_tolerance)) contacts.emplace_back(j, i);
            }
            s.spheres.push_back(std::move(p));
            velocity_at.push_back(t.get("velocity"));
        }
        refuse_sphere_jams(s, contacts, velocity_at);
    }

    // The first jammed sphere (toml_text.hpp), named at its velocity.
    void refuse_sphere_jams(const SphereScene& s,
                            const std::vector<std::pair<std::size_t, std::size_t>>& contacts,
                            const std::vector<const toml::node*>& velocity_at) const {
        if (const std::optional<toml_text::SphereJam> jam = toml_text::find_sphere_jam(s, contacts))
            fail(*velocity_at[jam->sphere], "sphere[" + std::to_string(jam->sphere) + "].velocity",
                 jam->message);
    }

    void read_fcc(const toml::node& n, SphereScene& s) const {
        const toml::array* a = n.as_array();
        if (a == nullptr || a->size() != 1) fail(n, "fcc", "expected one [[fcc]] table");
        const std::string field = "fcc";
        const toml::table& t = table_at(*a->get(0), field);
        check_keys(t, field, fcc_keys);
        const int line = static_cast<int>(t.source().begin.line);
        if (!s.spheres.empty())
            throw_scene_error(file_, line, "fcc",
                              "an FCC lattice fills the whole box: it cannot share it with "
                              "[[sphere]] entries");
        FccSpec spec;
        const toml::node& cells = required(t, "cells", field);
        if (const toml::array* c = cells.as_array()) {
            if (c->size() != 3) fail(cells, "fcc.cells", "expected a count or [nx, ny, nz]");
            for (std::size_t k = 0; k < 3; ++k)
                spec.cells[k] = static_cast<std::size_t>(
                    integer(*c->get(k), "fcc.cells[" + std::to_string(k) + "]", 1));
        } else {
            const auto each = static_cast<std::size_t>(integer(cells, "fcc.cells", 1));
            spec.cells = {each, each, each};
        }
        spec.packing_fraction =
            positive(required(t, "packing_fraction", field), "fcc.packing_fraction");
        if (const toml::node* v = t.get("mass")) spec.mass = positive(*v, "fcc.mass");
        if (const toml::node* v = t.get("temperature"))
            spec.temperature = number(*v, "fcc.temperature");
        if (const toml::node* v = t.get("color")) spec.color = rgb(*v, "fcc.color");
        if (const toml::node* v = t.get("seed"))
            spec.seed = static_cast<std::uint64_t>(integer(*v, "fcc.seed", 0));
        if (seed_override_) spec.seed = *seed_override_;
        if (const toml::node* v = t.get("tag")) spec.tag = text_value(*v, "fcc.tag");
        try {
            generate_fcc(s, spec, field);
        } catch (const Error& e) {
            fail_generated(t, field, e);
        }
    }

    void read_sphere_generators(const toml::node& n, SphereScene& s) const {
        const toml::array* a = n.as_array();
        if (a == nullptr) fail(n, "generate", "expected [[generate]] tables");
        for (std::size_t i = 0; i < a->size(); ++i) {
            const std::string field = "generate[" + std::to_string(i) + "]";
            const toml::table& t = table_at(*a->get(i), field);
            check_keys(t, field, generate3_keys);
            const auto key = [&](const char* name) { return field + "." + name; };
            SphereGenerateSpec g;
            g.seed = i + 1;
            if (const toml::node* v = t.get("count"))
                g.count = static_cast<std::size_t>(integer(*v, key("count"), 1));
            if (const toml::node* v = t.get("packing_fraction"))
                g.packing_fraction = positive(*v, key("packing_fraction"));
            const int line = static_cast<int>(t.source().begin.line);
            if (t.get("count") == nullptr && t.get("packing_fraction") == nullptr)
                throw_scene_error(file_, line, field, "give count or packing_fraction");
            g.radius = positive(required(t, "radius", field), key("radius"));
            if (const toml::node* v = t.get("mass")) g.mass = positive(*v, key("mass"));
            if (const toml::node* v = t.get("temperature"))
                g.temperature = number(*v, key("temperature"));
            if (const toml::node* v = t.get("speed")) g.speed = number(*v, key("speed"));
            if (t.get("temperature") != nullptr && g.speed)
                fail(*t.get("speed"), key("speed"), "give temperature or speed, not both");
            if (const toml::node* v = t.get("color")) g.color = rgb(*v, key("color"));
            if (const toml::node* v = t.get("seed"))
                g.seed = static_cast<std::uint64_t>(integer(*v, key("seed"), 0));
            if (seed_override_) g.seed = *seed_override_ + i;
            if (const toml::node* v = t.get("tag")) g.tag = text_value(*v, key("tag"));
            if (const toml::node* v = t.get("region")) {
                const toml::array* corners = v->as_array();
                if (corners == nullptr || corners->size() != 2)
                    fail(*v, key("region"), "expected [[x0, y0, z0], [x1, y1, z1]]");
                g.region_min = triple(*corners->get(0), key("region") + "[0]");
                g.region_max = triple(*corners->get(1), key("region") + "[1]");
            }
            try {
                generate_spheres(s, g, field);
            } catch (const Error& e) {
                fail_generated(t, field, e);
            }
        }
    }

    toml::table parse(std::string_view text) const {
        check_toml_limits(text, file_);
        try {
            return toml::parse(text, file_);
        } catch (const toml::parse_error& e) {
            throw_scene_error(file_, static_cast<int>(e.source().begin.line), "",
                              "TOML syntax error: " + std::string(e.description()));
        }
    }

    /// A replay_tag names discs the replay is to show: some disc must carry it.
    void check_replay_tag() const {
        const std::optional<std::string>& tag = scene_.render.replay_tag;
        if (!tag || replay_tag_node_ == nullptr) return;
        const bool carried = std::any_of(scene_.discs.begin(), scene_.discs.end(),
                                         [&](const Disc& d) { return d.tag == *tag; });
        if (!carried) {
            fail(*replay_tag_node_, "render.replay_tag",
                 "no disc has the tag \"" + *tag +
                     "\" (give the discs the replay is to show "
                     "tag = \"" +
                     *tag + "\")");
        }
    }

    /// The [box] table of either dimension: a 2D box has no depth (a 2D scene's `box.depth` was
    /// refused before, as a 3D key).
    template <typename SceneBox>
    void read_box(const toml::node& n, SceneBox& box) const {
        const toml::table& t = table_at(n, "box");
        check_keys(t, "box", box_keys);
        if (const toml::node* v = t.get("width")) box.width = box_side(*v, "box.width");
        if (const toml::node* v = t.get("height")) box.height = box_side(*v, "box.height");
        if constexpr (requires { box.depth; }) {
            if (const toml::node* v = t.get("depth")) box.depth = box_side(*v, "box.depth");
        }
        if (const toml::node* v = t.get("boundary")) {
            const std::string b = text_value(*v, "box.boundary");
            if (b == "walls") {
                box.boundary = Boundary::walls;
            } else if (b == "periodic") {
                box.boundary = Boundary::periodic;
            } else {
                fail(*v, "box.boundary", "expected \"walls\" or \"periodic\" (got \"" + b + "\")");
            }
        }
    }

    void read_render(const toml::node& n) {
        const toml::table& t = table_at(n, "render");
        check_keys(t, "render", render_keys);
        RenderHints& r = scene_.render;
        if (const toml::node* v = t.get("color_mode")) {
            r.color_mode = one_of(*v, "render.color_mode", color_mode_names);
        }
        if (const toml::node* v = t.get("trails")) r.trails = boolean(*v, "render.trails");
        if (const toml::node* v = t.get("overlays")) {
            if (v->is_boolean()) {
                r.overlays =
                    boolean(*v, "render.overlays") ? OverlayLevel::lesson : OverlayLevel::none;
            } else {
                r.overlays = one_of(*v, "render.overlays", overlay_level_names);
            }
        }
        if (const toml::node* v = t.get("theme")) r.theme = one_of(*v, "render.theme", theme_names);
        if (const toml::node* v = t.get("replay"))
            r.replay = one_of(*v, "render.replay", replay_choice_names);
        if (const toml::node* v = t.get("replay_tag")) {
            r.replay_tag = bounded_text(*v, "render.replay_tag", max_tag_chars);
            replay_tag_node_ = v;
        }
        if (const toml::node* v = t.get("histogram")) {
            // "auto" (the default: where it teaches) or a size.
            if (v->is_string() && v->as_string()->get() == "auto") {
                r.histogram.reset();
            } else {
                r.histogram = one_of(*v, "render.histogram", plot_size_names, "auto");
            }
        }
        if (const toml::node* v = t.get("caption")) {
            r.caption = caption(*v, "render.caption");
            r.caption_at = where(*v, "render.caption");
        }
        if (const toml::node* v = t.get("duration")) {
            r.duration = positive(*v, "render.duration");
            r.duration_at = where(*v, "render.duration");
        }
        if (const toml::node* v = t.get("speed")) {
            r.speed = positive(*v, "render.speed");
            r.speed_at = where(*v, "render.speed");
        }
        if (const toml::node* v = t.get("dt")) {
            r.dt = positive(*v, "render.dt");
            r.dt_at = where(*v, "render.dt");
        }
        if (const toml::node* v = t.get("camera"))
            r.camera = one_of(*v, "render.camera", camera_motion_names);
        if (const toml::node* v = t.get("projection"))
            r.projection = one_of(*v, "render.projection", projection_names);
        if (const toml::node* v = t.get("slab")) {
            r.slab = positive(*v, "render.slab");
            r.slab_at = where(*v, "render.slab");
        }
        if (const toml::node* v = t.get("captions")) read_captions(*v);
        if (const toml::node* v = t.get("questions")) read_questions(*v);
    }

    /// The value named in `table` (include/collide/render_options.hpp); `also`, when given, is
    /// one more name the caller handled itself, listed first.
    template <class E, std::size_t N>
    E one_of(const toml::node& n, const std::string& field,
             const std::array<NamedValue<E>, N>& table, std::string_view also = {}) const {
        const std::string value = text_value(n, field);
        Keys allowed;
        if (!also.empty()) allowed.emplace_back(also);
        for (const NamedValue<E>& entry : table) {
            if (entry.name == value) return entry.value;
            allowed.emplace_back(entry.name);
        }
        fail(n, field, "expected one of " + joined(allowed) + " (got \"" + clipped(value) + "\")");
    }

    std::string caption(const toml::node& n, const std::string& field) const {
        const std::string text = text_value(n, field);
        const std::size_t chars = utf8_length(text);
        if (chars > max_caption_chars) {
            fail(n, field,
                 "too long to fit on one line: at most " + std::to_string(max_caption_chars) +
                     " characters, got " + std::to_string(chars) +
                     " (split it into timed [[render.captions]])");
        }
        return text;
    }

    // A cue's `at`: seconds of video (number() refuses what is not finite), at or after 0,
    // after the previous cue of its kind (`what`), before the end of the video.
    double cue_time(const toml::node& at, const std::string& field, std::optional<double> previous,
                    const std::string& what) const {
        const double t = number(at, field);
        if (!(t >= 0.0)) fail(at, field, "must be >= 0 (got " + num(t) + ")");
        if (previous && !(t > *previous)) {
            fail(at, field,
                 "out of order: " + num(t) + " s is not after the previous " + what + " at " +
                     num(*previous) + " s");
        }
        const RenderHints& r = scene_.render;
        if (r.duration && t >= *r.duration) {
            fail(at, field,
                 "beyond the video: " + num(t) + " s, the video lasts " + num(*r.duration) + " s");
        }
        return t;
    }

    // [[render.captions]]: at (seconds of video, increasing, within the video) and text.
    void read_captions(const toml::node& n) {
        const toml::array* a = n.as_array();
        if (a == nullptr) fail(n, "render.captions", "expected [[render.captions]] tables");
        RenderHints& r = scene_.render;
        for (std::size_t i = 0; i < a->size(); ++i) {
            const std::string field = "render.captions[" + std::to_string(i) + "]";
            const toml::table& t = table_at(*a->get(i), field);
            check_keys(t, field, caption_keys);
            const toml::node* at = t.get("at");
            const toml::node* text = t.get("text");
            if (at == nullptr) fail(t, field + ".at", "missing (seconds of video)");
            if (text == nullptr) fail(t, field + ".text", "missing");
            CaptionCue cue;
            cue.at = cue_time(
                *at, field + ".at",
                r.captions.empty() ? std::nullopt : std::optional(r.captions.back().at), "caption");
            cue.text = caption(*text, field + ".text");
            if (const toml::node* v = t.get("event"))
                cue.event_text = caption(*v, field + ".event");
            if (const toml::node* v = t.get("time")) cue.time_text = caption(*v, field + ".time");
            if (const toml::node* hold = t.get("hold")) read_hold(*hold, field + ".hold", cue);
            cue.file = file_;
            cue.line = static_cast<int>(at->source().begin.line);
            r.captions.push_back(std::move(cue));
        }
    }

    // [[render.questions]]: at (seconds of video, increasing, within the video), kind, optional
    // text (the question's words, one caption line) and think (seconds, at least 2).
    void read_questions(const toml::node& n) {
        const toml::array* a = n.as_array();
        if (a == nullptr) fail(n, "render.questions", "expected [[render.questions]] tables");
        RenderHints& r = scene_.render;
        for (std::size_t i = 0; i < a->size(); ++i) {
            const std::string field = "render.questions[" + std::to_string(i) + "]";
            const toml::table& t = table_at(*a->get(i), field);
            check_keys(t, field, question_keys);
            const toml::node* at = t.get("at");
            const toml::node* kind = t.get("kind");
            if (at == nullptr) fail(t, field + ".at", "missing (seconds of video)");
            if (kind == nullptr)
                fail(t, field + ".kind", "missing (next-collision, how-many or will-see)");
            QuestionCue cue;
            cue.at =
                cue_time(*at, field + ".at",
                         r.questions.empty() ? std::nullopt : std::optional(r.questions.back().at),
                         "question");
            cue.kind = one_of(*kind, field + ".kind", question_kind_names);
            if (const toml::node* text = t.get("text")) cue.text = caption(*text, field + ".text");
            if (const toml::node* think = t.get("think")) {
                cue.think = number(*think, field + ".think");
                if (!(cue.think >= 2.0) || !std::isfinite(cue.think) || cue.think > 60.0) {
                    fail(*think, field + ".think",
                         "seconds a class thinks, from 2 to 60 (got " + num(cue.think) + ")");
                }
            }
            cue.file = file_;
            cue.line = static_cast<int>(at->source().begin.line);
            r.questions.push_back(std::move(cue));
        }
    }

    // hold = S: seconds of video the picture stays frozen on the caption, within the video.
    void read_hold(const toml::node& n, const std::string& field, CaptionCue& cue) const {
        cue.hold = number(n, field);
        if (!(cue.hold >= 0.0) || !std::isfinite(cue.hold))
            fail(n, field, "must be >= 0 seconds (got " + num(cue.hold) + ")");
        const RenderHints& r = scene_.render;
        if (r.duration && cue.at + cue.hold > *r.duration) {
            fail(n, field,
                 "beyond the video: held from " + num(cue.at) + " s for " + num(cue.hold) +
                     " s, the video lasts " + num(*r.duration) + " s");
        }
    }

    void read_includes(const toml::node& n) {
        if (n.is_string()) {
            read_include(n, "include");
            return;
        }
        const toml::array* a = n.as_array();
        if (a == nullptr) fail(n, "include", "expected a file name or a list of file names");
        for (std::size_t i = 0; i < a->size(); ++i)
            read_include(*a->get(i), "include[" + std::to_string(i) + "]");
    }

    void read_include(const toml::node& n, const std::string& field) {
        const std::filesystem::path path = base_dir_ / text_value(n, field);
        if (path.extension() != ".txt")
            fail(n, field,
                 "only algs4 .txt files can be included (got '" + path.filename().string() + "')");
        std::string text;
        try {
            text = read_scene_file(path);
        } catch (const Error& e) {
            fail(n, field, e.what());  // where the include is written, then what is wrong
        }
        included_bytes_ += text.size();
        if (included_bytes_ > max_scene_file_bytes)
            fail(n, field,
                 "the included files add up to more than " +
                     std::to_string(max_scene_file_bytes >> 20) + " MiB, the most a scene reads");
        ParsedScene part = parse_algs4(std::string_view(text), path.string());
        const std::size_t first = scene_.discs.size();
        for (Disc& d : part.scene.discs) scene_.discs.push_back(std::move(d));
        for (DiscSource run : part.origin.runs()) {
            run.first += first;
            origin_.add(std::move(run));
        }
    }

    void read_discs(const toml::node& n) {
        const toml::array* a = n.as_array();
        if (a == nullptr) fail(n, "disc", "expected [[disc]] tables");
        for (std::size_t i = 0; i < a->size(); ++i) {
            const std::string field = "disc[" + std::to_string(i) + "]";
            const toml::table& t = table_at(*a->get(i), field);
            check_keys(t, field, disc_keys);
            scene_.discs.push_back(read_disc(t, field));
            origin_.add({scene_.discs.size() - 1,
                         1,
                         file_,
                         {},
                         static_cast<int>(t.source().begin.line),
                         field});
        }
    }

    const toml::node& required(const toml::table& t, const std::string& key,
                               const std::string& prefix) const {
        const toml::node* v = t.get(key);
        if (v == nullptr)
            throw_scene_error(file_, static_cast<int>(t.source().begin.line), prefix + "." + key,
                              "missing (required)");
        return *v;
    }

    Disc read_disc(const toml::table& t, const std::string& prefix) const {
        Disc d;
        d.position = pair(required(t, "position", prefix), prefix + ".position");
        if (const toml::node* v = t.get("velocity")) d.velocity = pair(*v, prefix + ".velocity");
        d.radius = positive(required(t, "radius", prefix), prefix + ".radius");
        if (const toml::node* v = t.get("mass")) d.mass = positive(*v, prefix + ".mass");
        if (const toml::node* v = t.get("color")) d.color = rgb(*v, prefix + ".color");
        if (const toml::node* v = t.get("tag"))
            d.tag = bounded_text(*v, prefix + ".tag", max_tag_chars);
        return d;
    }

    void read_generators(const toml::node& n) {
        const toml::array* a = n.as_array();
        if (a == nullptr) fail(n, "generate", "expected [[generate]] tables");
        for (std::size_t i = 0; i < a->size(); ++i) {
            const std::string field = "generate[" + std::to_string(i) + "]";
            const toml::table& t = table_at(*a->get(i), field);
            check_keys(t, field, generate_keys);
            const GenerateSpec spec = read_spec(t, field, i);
            const std::size_t first = scene_.discs.size();
            const int line = static_cast<int>(t.source().begin.line);
            try {
                generate_discs(scene_, spec, field);
            } catch (const Error& e) {
                fail_generated(t, field, e);
            }
            origin_.add({first, scene_.discs.size() - first, file_, {}, line, field});
        }
    }

    GenerateSpec read_spec(const toml::table& t, const std::string& prefix, std::size_t index) {
        GenerateSpec g;
        // Blocks without a seed still get different streams (same stream = same pattern twice).
        g.seed = index + 1;
        const auto key = [&](const char* name) { return prefix + "." + name; };
        if (const toml::node* v = t.get("count"))
            g.count = static_cast<std::size_t>(integer(*v, key("count"), 1));
        if (const toml::node* v = t.get("packing_fraction"))
            g.packing_fraction = positive(*v, key("packing_fraction"));
        if (t.get("count") == nullptr && t.get("packing_fraction") == nullptr) {
            throw_scene_error(file_, static_cast<int>(t.source().begin.line), prefix,
                              "give count or packing_fraction");
        }
        g.radius = positive(required(t, "radius", prefix), key("radius"));
        if (const toml::node* v = t.get("mass")) g.mass = positive(*v, key("mass"));
        if (const toml::node* v = t.get("temperature"))
            g.temperature = number(*v, key("temperature"));
        if (const toml::node* v = t.get("speed")) g.speed = number(*v, key("speed"));
        if (t.get("temperature") != nullptr && g.speed)
            fail(*t.get("speed"), key("speed"), "give temperature or speed, not both");
        if (const toml::node* v = t.get("region")) read_region(*v, key("region"), g);
        if (const toml::node* v = t.get("color")) {
            if (v->is_string() && v->as_string()->get() == "speed") {
                g.color_by_speed = true;
                speed_colored_ = true;
            } else {
                g.color = rgb(*v, key("color"));
            }
        }
        if (const toml::node* v = t.get("seed"))
            g.seed = static_cast<std::uint64_t>(integer(*v, key("seed"), 0));
        if (seed_override_)
            g.seed = *seed_override_ + index;  // --seed: blocks still get different streams
        if (const toml::node* v = t.get("tag")) g.tag = bounded_text(*v, key("tag"), max_tag_chars);
        try {
            g.validate(prefix);
        } catch (const Error& e) {
            fail_generated(t, prefix, e);
        }
        return g;
    }

    void read_region(const toml::node& n, const std::string& field, GenerateSpec& g) const {
        const toml::array* a = n.as_array();
        if (a == nullptr || a->size() != 2) fail(n, field, "expected [[x0, y0], [x1, y1]]");
        g.region_min = pair(*a->get(0), field + "[0]");
        g.region_max = pair(*a->get(1), field + "[1]");
    }

    std::filesystem::path base_dir_;
    std::optional<std::uint64_t> seed_override_;
    Scene scene_;
    SceneOrigin origin_;
    bool speed_colored_ = false;
    const toml::node* replay_tag_node_ = nullptr;  ///< render.replay_tag, for its error
    std::uintmax_t included_bytes_ = 0;            ///< read through `include` so far
};

}  // namespace

Scene parse_toml_scene(std::string_view text, const std::string& file_label,
                       const std::filesystem::path& base_dir, const SceneOptions& options) {
    TomlReader reader(file_label, base_dir, options.seed);
    return reader.read(text);
}

AnyScene parse_any_toml_scene(std::string_view text, const std::string& file_label,
                              const std::filesystem::path& base_dir, const SceneOptions& options) {
    TomlReader reader(file_label, base_dir, options.seed);
    return reader.read_any(text);
}

Scene load_toml_scene(const std::filesystem::path& path, const SceneOptions& options) {
    const std::string text = read_scene_file(path);
    Scene scene = parse_toml_scene(text, path.string(), path.parent_path(), options);
    scene.name = path.stem().string();
    // A title from the file name is display text: valid UTF-8, so that an export reads back.
    if (scene.title.empty()) scene.title = valid_utf8(scene.name);
    return scene;
}

}  // namespace collide

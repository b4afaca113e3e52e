#include "algorithm_video.hpp"

#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <utility>

#include "cli_numbers.hpp"
#include "collide/error.hpp"
#include "collide/video/output.hpp"
#include "font_search.hpp"
#include "json_output.hpp"
#include "render_plan.hpp"

namespace collide::app {

OutputChoice algorithm_video_output_of(const AlgorithmVideoCli& v, std::string_view stem) {
    const auto if_given = [](const CLI::Option* option, const std::string& value) {
        return given(option) ? std::optional(value) : std::nullopt;
    };
    return resolve_output(if_given(v.format_opt, v.format), if_given(v.output_opt, v.output),
                          v.last_frame || given(v.at_opt), stem);
}

AlgorithmVideoGeometry algorithm_video_geometry_of(const AlgorithmVideoCli& v, FrameSize minimum,
                                                   std::string_view what_stays_legible) {
    const QualityPreset preset = quality_preset(v.quality, "-q");
    AlgorithmVideoGeometry g{preset.width, preset.height, preset.fps};
    if (given(v.size_opt)) {
        const FrameSize size = parse_frame_size(v.size, "--size");
        g.width = size.width;
        g.height = size.height;
    }
    if (g.width < minimum.width || g.height < minimum.height) {
        throw_option_error(
            given(v.size_opt) ? "--size" : "-q",
            fmt::format("{}x{} is too small for {}; at least {}x{}", g.width, g.height,
                        what_stays_legible, minimum.width, minimum.height));
    }
    if (given(v.fps_opt)) g.fps = checked_fps(v.fps);
    return g;
}

AlgorithmVideoDestination algorithm_video_destination_of(const AlgorithmVideoCli& v,
                                                         std::string_view stem, double duration,
                                                         const std::string& title) {
    if (given(v.at_opt) && !(v.at >= 0.0 && v.at <= duration)) {
        throw_option_error("--at", fmt::format("{}", v.at),
                           fmt::format("a time within the video, 0..{:.2f} s", duration));
    }
    AlgorithmVideoDestination d;
    d.output = algorithm_video_output_of(v, stem);
    d.subtitles = subtitle_output_of(v, d.output);
    d.chapters = chapter_output_of(v, d.output, title);
    if (d.output.default_path) std::filesystem::create_directories(d.output.path.parent_path());
    video::check_output_writable(
        d.output.path, !d.output.still && d.output.format == video::VideoFormat::png_sequence);
    d.still_time = given(v.at_opt) ? v.at : duration;
    return d;
}

void check_timeline_json(const std::string& path, const AlgorithmVideoDestination& destination) {
    if (path.empty()) return;
    if (destination.output.still)
        throw_option_error("--timeline-json", "only for videos (a still has no timeline)");
    std::vector<io::NamedOutput> outputs;
    outputs.push_back({"-o", destination.output.path,
                       destination.output.format == video::VideoFormat::png_sequence});
    outputs.push_back({"--timeline-json", path, false});
    if (!destination.subtitles.file.empty())
        outputs.push_back({"--subtitles-file", destination.subtitles.file, false});
    if (!destination.chapters.file.empty())
        outputs.push_back({"--chapters-file", destination.chapters.file, false});
    if (!destination.chapters.slides.empty())
        outputs.push_back({"--slides", destination.chapters.slides, true});
    if (!destination.chapters.handout.empty())
        outputs.push_back({"--handout", destination.chapters.handout, false});
    io::check_distinct_outputs(outputs);
}

std::optional<io::OutputFile> open_timeline_json(const std::string& path,
                                                 const AlgorithmVideoDestination& destination,
                                                 const show::Timeline& timeline) {
    if (path.empty()) return std::nullopt;
    check_timeline_json(path, destination);
    std::optional<io::OutputFile> file;
    file.emplace(path, io::OutputOptions{"--timeline-json"});
    file->write(drawn_timeline_json(timeline));
    return file;
}

std::string drawn_timeline_json(const show::Timeline& timeline) {
    Json segments = Json::array();
    for (const show::Segment& segment : timeline.segments) {
        segments.push_back(Json{{"kind", show::segment_kind_name(segment.kind)},
                                {"start", segment.start},
                                {"end", segment.end},
                                {"first_frame", segment.first_frame},
                                {"end_frame", segment.end_frame},
                                {"caption", segment.caption}});
    }
    return json_text(Json{{"fps", timeline.fps},
                          {"frames", timeline.frame_count()},
                          {"seconds", static_cast<double>(timeline.frame_count()) / timeline.fps},
                          {"segments", std::move(segments)}});
}

}  // namespace collide::app

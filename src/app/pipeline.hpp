#pragma once
/// \file
/// The frame pipeline of `collide render`: simulate -> render -> encode, overlapped on threads.
///
///   simulation thread    show::CollisionSimulation: advances the engines to each frame time,
///                        describes their state               -> BoundedQueue<CollisionState>
///   calling thread       owns the GL context: show::CollisionProgram fills the frame's view,
///                        the Renderer paints it (and shows it in the --preview window)
///                                                            -> VideoWriter::write
///   encoder thread(s)    inside VideoWriter (RGBA -> yuv420p, libx264 and its own threads)
///
/// Every stage sees frames strictly in order and nothing depends on wall time, so the output is
/// byte-identical whatever the thread timing (same scene, options -> same file).

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "collide/io/file.hpp"
#include "collide/render/renderer.hpp"
#include "collide/scene.hpp"
#include "collide/scene3.hpp"
#include "collide/show/collision_program.hpp"
#include "interrupt.hpp"
#include "progress.hpp"
#include "render_plan.hpp"
#include "video_job.hpp"

namespace collide::app {

/// What happened, for the summary line.
struct PipelineResult {
    std::int64_t frames = 0;
    double sim_time = 0.0;              ///< simulation time of the last frame
    std::vector<Measurements> engines;  ///< in panel order
    std::vector<std::string> notices;   ///< from the encoder (size rounded, GIF rate reduced)
    int output_width = 0;
    int output_height = 0;
    double output_fps = 0.0;
    std::string layout_json;  ///< the last frame's rectangles (when plan.layout_json is set)
};

/// Renders plan.clock's frames into plan.output through the video job (video_job.hpp): a video
/// (MP4, GIF or PNG sequence), or for a still (thumbnail, --last-frame) only the last frame as a
/// PNG, every earlier frame time still simulated (so the time-driven engine takes the video's
/// steps) and the frames that feed the trails drawn, so the image equals the video's frame.
/// Nothing appears at plan.output unless every frame was produced and the file finished.
/// `layout_file` (may be null: no --layout-json) receives the last frame's rectangles once the
/// output is complete, before either is put in place: a failure to write one leaves both
/// destinations untouched. Throws Error: input for bad options, runtime for GL/encoder failures
/// or an interrupt.
/// `subtitles`: the video's cues (show::subtitle_cues of the timeline) go into the MP4 and/or a
/// sidecar as it says; the sidecar too appears only with the video.
/// `chapters`: the timeline's chapters (show::timeline_chapters) go into the MP4, a chapters
/// file and/or a slide folder as it says, likewise only with the video.
/// `scene`: discs, or spheres drawn as spheres and planned through their stand-in.
PipelineResult run_render(show::SceneView scene, const RenderPlan& plan, const JobHooks& hooks,
                          io::OutputFile* layout_file = nullptr,
                          const SubtitleOutput& subtitles = {}, const ChapterOutput& chapters = {});

}  // namespace collide::app

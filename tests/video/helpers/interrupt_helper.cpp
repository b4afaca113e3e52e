// Test helper for collide_video_tests: encodes a 160x90 MP4 slowly (forever) to argv[1] with the
// app's interrupt guard, the way `collide render` does, until SIGINT/SIGTERM arrives. Expected:
// exit status 1 with a message, the temporary removed, the destination untouched.

#include <chrono>
#include <cstdio>
#include <thread>

#include "collide/error.hpp"
#include "collide/video/video_writer.hpp"
#include "interrupt.hpp"

int main(int argc, char** argv) {
    if (argc != 2) return 2;
    try {
        collide::app::InterruptGuard interrupts;
        collide::video::set_libav_verbose(false);
        collide::video::VideoOptions options;
        options.path = argv[1];
        options.width = 160;
        options.height = 90;
        options.preset = "ultrafast";
        options.cancel = &interrupts.flag();
        collide::video::VideoWriter writer(options);
        collide::Image frame(160, 90);
        for (int i = 0; i < 100000; ++i) {
            interrupts.throw_if_requested();
            frame.rgba.assign(frame.rgba.size(), static_cast<std::uint8_t>(i * 7));
            writer.write(frame);
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        writer.finish();
        return 0;
    } catch (const collide::Error& e) {
        std::fprintf(stderr, "interrupt_helper: error: %s\n", e.what());
        return e.exit_code();
    }
}

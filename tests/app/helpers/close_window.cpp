// Test helper: plays the user who closes the `--preview` window. Waits for a viewable top-level
// window with exactly the given title, asks it to close the way a window manager's close button
// does (a WM_DELETE_WINDOW client message), then waits until it is no longer viewable.
//
// Usage: close_window TITLE TIMEOUT_SECONDS
// Exit 0: closed; 1: no such window appeared in time; 2: usage or no display; 3: still open.
#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>

namespace {

using Clock = std::chrono::steady_clock;
constexpr auto poll_interval = std::chrono::milliseconds(10);

// The window may vanish between listing and asking about it: that is not an error here.
int ignore_x_errors(Display* /*display*/, XErrorEvent* /*event*/) {
    return 0;
}

bool is_viewable(Display* display, Window window) {
    XWindowAttributes attributes{};
    return XGetWindowAttributes(display, window, &attributes) != 0 &&
           attributes.map_state == IsViewable;
}

bool has_title(Display* display, Window window, const std::string& title) {
    char* name = nullptr;
    if (XFetchName(display, window, &name) == 0 || name == nullptr) return false;
    const bool same = title == name;
    XFree(name);
    return same;
}

// Without a window manager (plain Xvfb) top-level windows are the root window's children.
Window find_window(Display* display, const std::string& title) {
    Window root_return = 0;
    Window parent = 0;
    Window* children = nullptr;
    unsigned int count = 0;
    Window found = 0;
    if (XQueryTree(display, DefaultRootWindow(display), &root_return, &parent, &children, &count) ==
        0) {
        return 0;
    }
    for (unsigned int i = 0; i < count && found == 0; ++i) {
        if (is_viewable(display, children[i]) && has_title(display, children[i], title)) {
            found = children[i];
        }
    }
    if (children != nullptr) XFree(children);
    return found;
}

void request_close(Display* display, Window window) {
    XEvent event{};
    event.xclient.type = ClientMessage;
    event.xclient.window = window;
    event.xclient.message_type = XInternAtom(display, "WM_PROTOCOLS", False);
    event.xclient.format = 32;
    event.xclient.data.l[0] = static_cast<long>(XInternAtom(display, "WM_DELETE_WINDOW", False));
    event.xclient.data.l[1] = CurrentTime;
    XSendEvent(display, window, False, NoEventMask, &event);
    XFlush(display);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: close_window TITLE TIMEOUT_SECONDS\n");
        return 2;
    }
    const std::string title = argv[1];
    const auto deadline = Clock::now() + std::chrono::seconds(std::atoi(argv[2]));
    Display* display = XOpenDisplay(nullptr);
    if (display == nullptr) {
        std::fprintf(stderr, "close_window: cannot open the display\n");
        return 2;
    }
    XSetErrorHandler(ignore_x_errors);
    Window window = 0;
    while ((window = find_window(display, title)) == 0) {
        if (Clock::now() > deadline) {
            std::fprintf(stderr, "close_window: no window titled '%s'\n", title.c_str());
            XCloseDisplay(display);
            return 1;
        }
        std::this_thread::sleep_for(poll_interval);
    }
    request_close(display, window);
    while (is_viewable(display, window)) {
        if (Clock::now() > deadline) {
            std::fprintf(stderr, "close_window: '%s' is still open\n", title.c_str());
            XCloseDisplay(display);
            return 3;
        }
        std::this_thread::sleep_for(poll_interval);
    }
    XCloseDisplay(display);
    return 0;
}

// GLFW backend: the context of a hidden window (needs a display, e.g. Xvfb). The renderer draws
// into its own FBO of the requested size, exactly as with OSMesa, so the pixels match.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <memory>
#include <mutex>
#include <string>

#include "backends.hpp"
#include "collide/error.hpp"
#include "glfw_library.hpp"

namespace collide::render {

GlfwLibrary::~GlfwLibrary() {
    glfwTerminate();
}

std::shared_ptr<GlfwLibrary> GlfwLibrary::acquire(std::string& why) {
    // GLFW's state is process-global by design; this is the one place that mirrors it.
    static std::mutex mutex;
    static std::weak_ptr<GlfwLibrary> live;
    const std::lock_guard lock(mutex);
    if (auto library = live.lock()) return library;
    if (glfwInit() != GLFW_TRUE) {
        const char* description = nullptr;
        glfwGetError(&description);
        why = description != nullptr ? description : "glfwInit failed";
        return nullptr;
    }
    std::shared_ptr<GlfwLibrary> library(new GlfwLibrary());
    live = library;
    return library;
}

namespace {

class GlfwContext final : public Context {
  public:
    GlfwContext(std::shared_ptr<GlfwLibrary> library, GLFWwindow* window)
        : library_(std::move(library)), window_(window) {}
    ~GlfwContext() override { glfwDestroyWindow(window_); }
    GlfwContext(const GlfwContext&) = delete;
    GlfwContext& operator=(const GlfwContext&) = delete;

    [[nodiscard]] Backend backend() const noexcept override { return Backend::glfw; }
    void make_current() override { glfwMakeContextCurrent(window_); }
    [[nodiscard]] GlProcLoader proc_loader() const noexcept override {
        return [](const char* name) -> GlProc { return glfwGetProcAddress(name); };
    }

  private:
    std::shared_ptr<GlfwLibrary> library_;  // declared first: outlives the window
    GLFWwindow* window_ = nullptr;
};

}  // namespace

std::unique_ptr<Context> try_make_glfw_context(int width, int height, std::string& why) {
    auto library = GlfwLibrary::acquire(why);
    if (!library) return nullptr;
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWwindow* window = glfwCreateWindow(width, height, "collide (offscreen)", nullptr, nullptr);
    if (window == nullptr) {
        const char* description = nullptr;
        glfwGetError(&description);
        throw_runtime_error(std::string("GLFW: failed to create a GL 3.3 core context: ") +
                            (description != nullptr ? description : "unknown error"));
    }
    auto context = std::make_unique<GlfwContext>(std::move(library), window);
    context->make_current();
    return context;
}

}  // namespace collide::render

#pragma once
// Internal: GLFW's process-wide initialisation, shared by every GLFW window we own. GLFW itself
// is a process-global library; this owner makes init/terminate follow the lifetime of the
// windows that need it (terminate runs when the last window is gone).
#include <memory>
#include <string>

namespace collide::render {

class GlfwLibrary {
  public:
    GlfwLibrary(const GlfwLibrary&) = delete;
    GlfwLibrary& operator=(const GlfwLibrary&) = delete;
    ~GlfwLibrary();

    /// The live library or a fresh initialisation; null when glfwInit fails (no display), with
    /// GLFW's description in `why`.
    [[nodiscard]] static std::shared_ptr<GlfwLibrary> acquire(std::string& why);

  private:
    GlfwLibrary() = default;
};

}  // namespace collide::render

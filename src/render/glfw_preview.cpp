// The `--preview` window: a visible GLFW window with its own context showing finished frames.
#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <memory>
#include <string>

#include "backends.hpp"
#include "collide/error.hpp"
#include "collide/render/preview.hpp"
#include "gl_objects.hpp"
#include "glfw_library.hpp"
#include "shaders.hpp"

namespace collide::render {
namespace {

struct WindowDeleter {
    void operator()(GLFWwindow* window) const noexcept { glfwDestroyWindow(window); }
};

class GlfwPreview final : public PreviewWindow {
  public:
    GlfwPreview(std::shared_ptr<GlfwLibrary> library, GLFWwindow* window)
        : library_(std::move(library)), window_(window) {
        glfwMakeContextCurrent(window_.get());
        if (gladLoadGLContext(&gl_, glfwGetProcAddress) == 0) {
            throw_runtime_error("GLFW: cannot load GL entry points for the preview window");
        }
        glfwSwapInterval(0);  // never let the display's refresh rate slow the encoder down
        program_ =
            make_program(gl_, shaders::present_vert, shaders::present_frag, "preview shader");
        vertex_array_ = make_vertex_array(gl_);
        texture_ = make_texture(gl_);
        gl_.BindTexture(GL_TEXTURE_2D, texture_.get());
        gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    ~GlfwPreview() override {
        // GL objects are deleted (member destructors) with their own context current.
        glfwMakeContextCurrent(window_.get());
    }
    GlfwPreview(const GlfwPreview&) = delete;
    GlfwPreview& operator=(const GlfwPreview&) = delete;

    bool show(const Image& image) override {
        if (closed_) return false;
        glfwPollEvents();
        if (glfwWindowShouldClose(window_.get())) {
            closed_ = true;
            return false;
        }
        glfwMakeContextCurrent(window_.get());
        upload(image);
        // Shown with its first frame, so a window opened before rendering starts is never blank.
        if (glfwGetWindowAttrib(window_.get(), GLFW_VISIBLE) == GLFW_FALSE) {
            glfwShowWindow(window_.get());
        }
        int width = 0;
        int height = 0;
        glfwGetFramebufferSize(window_.get(), &width, &height);
        gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
        gl_.Viewport(0, 0, width, height);
        gl_.UseProgram(program_.get());
        gl_.BindVertexArray(vertex_array_.get());
        gl_.DrawArrays(GL_TRIANGLES, 0, 3);
        check_gl(gl_, "preview window");
        glfwSwapBuffers(window_.get());
        return true;
    }

  private:
    void upload(const Image& image) {
        gl_.ActiveTexture(GL_TEXTURE0);
        gl_.BindTexture(GL_TEXTURE_2D, texture_.get());
        gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
        if (image.width != texture_width_ || image.height != texture_height_) {
            gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA,
                           GL_UNSIGNED_BYTE, image.rgba.data());
            texture_width_ = image.width;
            texture_height_ = image.height;
        } else {
            gl_.TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, GL_RGBA,
                              GL_UNSIGNED_BYTE, image.rgba.data());
        }
    }

    // Declaration order is destruction order reversed: the GL objects go first, then the
    // window (and its context), then, if this was the last user, GLFW itself.
    std::shared_ptr<GlfwLibrary> library_;
    std::unique_ptr<GLFWwindow, WindowDeleter> window_;
    GladGLContext gl_{};
    GlObject program_;
    GlObject vertex_array_;
    GlObject texture_;
    int texture_width_ = 0;
    int texture_height_ = 0;
    bool closed_ = false;
};

}  // namespace

std::unique_ptr<PreviewWindow> open_preview(int width, int height, const char* title,
                                            const NoticeSink& notice) {
    std::string why;
    auto library = GlfwLibrary::acquire(why);
    if (!library) {
        emit_notice(notice, "notice: no display for --preview (" + why + "); continuing without");
        return nullptr;
    }
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);  // until show() has a frame for it
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWwindow* window = glfwCreateWindow(width, height, title, nullptr, nullptr);
    if (window == nullptr) {
        emit_notice(notice, "notice: cannot open the preview window; continuing without");
        return nullptr;
    }
    return std::make_unique<GlfwPreview>(std::move(library), window);
}

}  // namespace collide::render

#include "gl_objects.hpp"

#include <cstdio>
#include <new>
#include <string>
#include <utility>

#include "collide/error.hpp"

namespace collide::render {

GlObject make_buffer(const GladGLContext& gl) {
    GLuint name = 0;
    gl.GenBuffers(1, &name);
    return {gl, name, [](const GladGLContext& g, GLuint n) { g.DeleteBuffers(1, &n); }};
}

GlObject make_vertex_array(const GladGLContext& gl) {
    GLuint name = 0;
    gl.GenVertexArrays(1, &name);
    return {gl, name, [](const GladGLContext& g, GLuint n) { g.DeleteVertexArrays(1, &n); }};
}

GlObject make_texture(const GladGLContext& gl) {
    GLuint name = 0;
    gl.GenTextures(1, &name);
    return {gl, name, [](const GladGLContext& g, GLuint n) { g.DeleteTextures(1, &n); }};
}

GlObject make_framebuffer(const GladGLContext& gl) {
    GLuint name = 0;
    gl.GenFramebuffers(1, &name);
    return {gl, name, [](const GladGLContext& g, GLuint n) { g.DeleteFramebuffers(1, &n); }};
}

GlObject make_renderbuffer(const GladGLContext& gl) {
    GLuint name = 0;
    gl.GenRenderbuffers(1, &name);
    return {gl, name, [](const GladGLContext& g, GLuint n) { g.DeleteRenderbuffers(1, &n); }};
}

namespace {

GlObject compile_shader(const GladGLContext& gl, GLenum type, const char* source,
                        const std::string& what) {
    GlObject shader(gl, gl.CreateShader(type),
                    [](const GladGLContext& g, GLuint n) { g.DeleteShader(n); });
    gl.ShaderSource(shader.get(), 1, &source, nullptr);
    gl.CompileShader(shader.get());
    GLint ok = GL_FALSE;
    gl.GetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        char log[2048] = {};
        gl.GetShaderInfoLog(shader.get(), sizeof log, nullptr, log);
        throw_runtime_error("GL: cannot compile the " + what + ": " + log);
    }
    return shader;
}

}  // namespace

GlObject make_program(const GladGLContext& gl, const char* vertex_source,
                      const char* fragment_source, const std::string& what) {
    GlObject vertex = compile_shader(gl, GL_VERTEX_SHADER, vertex_source, what + " (vertex)");
    GlObject fragment =
        compile_shader(gl, GL_FRAGMENT_SHADER, fragment_source, what + " (fragment)");
    GlObject program(gl, gl.CreateProgram(),
                     [](const GladGLContext& g, GLuint n) { g.DeleteProgram(n); });
    gl.AttachShader(program.get(), vertex.get());
    gl.AttachShader(program.get(), fragment.get());
    gl.LinkProgram(program.get());
    GLint ok = GL_FALSE;
    gl.GetProgramiv(program.get(), GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        char log[2048] = {};
        gl.GetProgramInfoLog(program.get(), sizeof log, nullptr, log);
        throw_runtime_error("GL: cannot link the " + what + ": " + log);
    }
    return program;
}

void check_gl(const GladGLContext& gl, const char* where) {
    const GLenum error = gl.GetError();
    // Memory is main's to report, as every allocation that fails: "out of memory".
    if (error == GL_OUT_OF_MEMORY) throw std::bad_alloc();
    if (error != GL_NO_ERROR) {
        char code[16];
        std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(error));
        throw_runtime_error(std::string("GL error ") + code + " in " + where);
    }
}

}  // namespace collide::render

#pragma once
// Internal: GLSL sources from shaders/, embedded at build time (cmake/EmbedShaders.cmake).
namespace collide::render::shaders {
extern const char* const disc_vert;
extern const char* const disc_frag;
extern const char* const overlay_vert;
extern const char* const overlay_frag;
extern const char* const present_vert;
extern const char* const present_frag;
extern const char* const sphere_vert;
extern const char* const sphere_frag;
}  // namespace collide::render::shaders

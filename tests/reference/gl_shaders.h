// The reference's GLSL sources (gl_shaders.cpp). A program is the version line, its
// #defines (gl_scene.cpp), the light prelude, then the stage's source.
#pragma once
#include "osmesa_target.h"

namespace glref {

extern const char* const kLightPrelude;    // both stages: point and spot lights
extern const char* const kVertexShader;
extern const char* const kFragmentShader;
extern const char* const kDepthVertexShader;    // the shadow maps' depth pass (gl_shadows.cpp), complete
extern const char* const kDepthFragmentShader;

// A program of two complete sources (the depth pass's, the sky's); throws naming `what`.
GLuint standalone_program(const char* vertex, const char* fragment, const char* what);

}  // namespace glref

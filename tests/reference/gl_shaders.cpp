// The reference's GLSL: the scene format's formulas as the shaders llvmpipe runs.
#include "gl_shaders.h"

#include <stdexcept>
#include <string>

namespace glref {

// Each (shading model, texture, light count) combination is compiled as its own program,
// with the choices as #defines, as a real OpenGL application would: llvmpipe then runs no
// branch on material state per fragment (fair timing), and the formulas read as in the spec.
// Both stages: the point and spot lights' uniforms and term (docs/scene-format.md
// "Point and spot lights").
const char* const kLightPrelude = R"(
#if POSITIONAL > 0
uniform vec3 u_pl_position[POSITIONAL];
uniform vec3 u_pl_color[POSITIONAL];       // color times intensity
uniform float u_pl_inv_range2[POSITIONAL]; // 1 / range^2, 0 without a range
uniform vec3 u_pl_spot_dir[POSITIONAL];
uniform vec2 u_pl_cone[POSITIONAL];        // spot: 1 / (cos inner - cos outer), -cos outer * that; point: 0, 1
vec3 positional_light(int i, vec3 p, out vec3 l) {
    vec3 lv = u_pl_position[i] - p;
    float d2 = max(dot(lv, lv), 1e-8);
    l = lv / sqrt(d2);
    float t = d2 * u_pl_inv_range2[i];
    float k = clamp(1.0 - t * t, 0.0, 1.0) / d2;
    float a = clamp(dot(-l, u_pl_spot_dir[i]) * u_pl_cone[i].x + u_pl_cone[i].y, 0.0, 1.0);
    return u_pl_color[i] * (k * a * a);
}
#endif
)";

const char* const kVertexShader = R"(
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_color;
layout(location = 4) in vec4 a_tangent;
uniform mat4 u_mvp;
uniform mat4 u_model;
uniform mat3 u_normal_matrix;
uniform vec3 u_ambient;
uniform vec3 u_to_light[8];
uniform vec3 u_light_color[8];
INTERP out vec3 v_world;
INTERP out vec3 v_normal;
INTERP out vec2 v_uv;
INTERP out vec4 v_color;
INTERP out vec3 v_intensity;
#if NORMAL_MAP
INTERP out vec4 v_tangent;
#endif
void main() {
    v_world = (u_model * vec4(a_pos, 1.0)).xyz;
    v_normal = u_normal_matrix * a_normal;
#if NORMAL_MAP
    v_tangent = vec4(mat3(u_model) * a_tangent.xyz, a_tangent.w);
#endif
    v_uv = a_uv;
    v_color = a_color;
    v_intensity = u_ambient;
#if SHADING == 2
    vec3 n = normalize(v_normal);
    for (int i = 0; i < LIGHTS; ++i) v_intensity += u_light_color[i] * max(0.0, dot(n, u_to_light[i]));
#if POSITIONAL > 0
    for (int i = 0; i < POSITIONAL; ++i) {
        vec3 l;
        vec3 c = positional_light(i, v_world, l);
        v_intensity += c * max(0.0, dot(n, l));
    }
#endif
#endif
    vec4 clip = u_mvp * vec4(a_pos, 1.0);
    // Flip y: GL window row 0 (the first row in memory) becomes the top row of the picture,
    // so llvmpipe's fill rule and sample pattern apply in the picture as stored.
    gl_Position = vec4(clip.x, -clip.y, clip.z, clip.w);
}
)";

const char* const kFragmentShader = R"(
INTERP in vec3 v_world;
INTERP in vec3 v_normal;
INTERP in vec2 v_uv;
INTERP in vec4 v_color;
INTERP in vec3 v_intensity;
#if NORMAL_MAP
INTERP in vec4 v_tangent;
uniform sampler2D u_normal_texture;
uniform float u_normal_scale;
#endif
// SHADING: 0 unlit, 1 flat, 2 gouraud, 3 lambert, 4 blinn_phong, 5 normals, 6 depth, 7 phong, 8 pbr
uniform sampler2D u_texture;
uniform vec4 u_color;
uniform vec3 u_specular;
uniform float u_shininess;
uniform vec3 u_eye;
uniform vec3 u_ambient;
uniform vec3 u_to_light[8];
uniform vec3 u_light_color[8];
uniform float u_alpha_cutoff;
uniform float u_exposure;
out vec4 frag;
#if SHADING == 8
// glTF 2.0 appendix B: Schlick's Fresnel, GGX, the height-correlated Smith visibility; a
// light adds pi f c (N.L) (the pi: a light's color is what a white diffuse surface reflects).
#define PI 3.14159265358979
uniform float u_metallic;
uniform float u_roughness;
uniform float u_occlusion_strength;
uniform vec3 u_emissive;
uniform sampler2D u_mr_texture;
uniform sampler2D u_occlusion_texture;
uniform sampler2D u_emissive_texture;
#if ENVIRONMENT
// Image-based lighting (environment_lighting.h), from softraster's precomputed maps.
uniform vec3 u_env_sh[9];              // E/pi's coefficients
uniform sampler2D u_env_specular;      // prefiltered levels 0..5 as the mipmap
uniform sampler2D u_env_lut;           // A, B by (N.V, roughness)
uniform float u_env_intensity;
vec3 environment_light(vec3 c_diff, vec3 f0, vec3 n, vec3 v, float nv, float roughness, float occlusion) {
    vec3 r = 2.0 * dot(n, v) * n - v;
    vec2 ab = texture(u_env_lut, vec2(nv, roughness)).rg;
    vec3 k = f0 * ab.x + ab.y;
    vec3 e = u_env_sh[0] + u_env_sh[1] * n.y + u_env_sh[2] * n.z + u_env_sh[3] * n.x + u_env_sh[4] * (n.x * n.y) +
             u_env_sh[5] * (n.y * n.z) + u_env_sh[6] * (3.0 * n.z * n.z - 1.0) + u_env_sh[7] * (n.x * n.z) +
             u_env_sh[8] * (n.x * n.x - n.y * n.y);
    vec3 diffuse = c_diff * max(e, vec3(0.0)) * (1.0 - k);
    vec2 uv = vec2(0.5 + atan(r.x, -r.z) * 0.159154943091895, acos(clamp(r.y, -1.0, 1.0)) * 0.318309886183791);
    vec3 s = textureLod(u_env_specular, uv, clamp(roughness * 5.0, 0.0, 5.0)).rgb;
    return (diffuse + s * k) * (occlusion * u_env_intensity);
}
#endif
vec3 pbr_light(vec3 c_diff, vec3 f0, float a2, vec3 n, vec3 v, vec3 l, float nv) {
    float nl = dot(n, l);
    if (!(nl > 0.0)) return vec3(0.0);
    vec3 h = normalize(l + v);
    float nh = max(0.0, dot(n, h)), vh = max(0.0, dot(v, h));
    vec3 F = f0 + (1.0 - f0) * pow(1.0 - vh, 5.0);
    float dd = nh * nh * (a2 - 1.0) + 1.0;
    float D = a2 / (PI * dd * dd);
    float vis = 1.0 / ((nl + sqrt(a2 + (1.0 - a2) * nl * nl)) * (nv + sqrt(a2 + (1.0 - a2) * nv * nv)));
    return ((1.0 - F) * c_diff / PI + F * (D * vis)) * (PI * nl);
}
#endif
// Shadows (SHADOWS maps, gl_shadows.h): a shadowed light's color times its visibility at P,
// the share of the PCF kernel's texels at or beyond P's depth seen from the light.
uniform int u_shadow_of[8];  // directional light i's map, or SHADOWS for none
#if POSITIONAL > 0
uniform int u_pl_shadow[POSITIONAL];
#endif
#if SHADOWS > 0
uniform mat4 u_shadow_matrix[SHADOWS * 6];  // map s's face f: s * 6 + f
uniform vec3 u_shadow_offset[SHADOWS * 6];  // bias toward the light
uniform int u_shadow_faces[SHADOWS];        // 1, or a point light's cube: 6
uniform vec3 u_shadow_light[SHADOWS];       // a cube's center
uniform int u_shadow_size[SHADOWS];
uniform int u_shadow_pcf[SHADOWS];
uniform sampler2DArray u_shadow_map0;
#if SHADOWS > 1
uniform sampler2DArray u_shadow_map1;
#endif
#if SHADOWS > 2
uniform sampler2DArray u_shadow_map2;
#endif
#if SHADOWS > 3
uniform sampler2DArray u_shadow_map3;
#endif
// A cube's face: the major axis of P - light, x before y before z on ties, + where >= 0.
int shadow_face(int s, vec3 p) {
    if (u_shadow_faces[s] == 1) return 0;
    vec3 d = p - u_shadow_light[s], a = abs(d);
    if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0 : 1;
    if (a.y >= a.z) return d.y >= 0.0 ? 2 : 3;
    return d.z >= 0.0 ? 4 : 5;
}
float shadow_visibility(sampler2DArray map, int s, vec3 p) {
    int f = shadow_face(s, p);
    vec3 b = p + u_shadow_offset[s * 6 + f];
    mat4 m = u_shadow_matrix[s * 6 + f];
    vec4 q = ((m[0] * b.x + m[1] * b.y) + m[2] * b.z) + m[3];
    if (!(q.w > 0.0)) return 1.0;
    float iw = 1.0 / q.w, half_size = 0.5 * float(u_shadow_size[s]);
    float x = (q.x * iw + 1.0) * half_size, y = (1.0 - q.y * iw) * half_size, z = (q.z * iw + 1.0) * 0.5;
    int last = u_shadow_size[s] - 1, r = u_shadow_pcf[s];
    // window row 0 is the top, as in the depth pass (the vertex shader's y flip)
    int i = clamp(int(floor(clamp(x, -1.0, float(u_shadow_size[s])))), 0, last);
    int j = clamp(int(floor(clamp(y, -1.0, float(u_shadow_size[s])))), 0, last);
    int lit = 0;
    for (int dj = -r; dj <= r; ++dj)
        for (int di = -r; di <= r; ++di)
            if (z <= texelFetch(map, ivec3(clamp(i + di, 0, last), clamp(j + dj, 0, last), f), 0).r) ++lit;
    return float(lit) * (1.0 / float((2 * r + 1) * (2 * r + 1)));
}
#endif
float vis[SHADOWS + 1];
void shadow_visibilities() {
    vis[SHADOWS] = 1.0;
#if SHADOWS > 0
    vis[0] = shadow_visibility(u_shadow_map0, 0, v_world);
#endif
#if SHADOWS > 1
    vis[1] = shadow_visibility(u_shadow_map1, 1, v_world);
#endif
#if SHADOWS > 2
    vis[2] = shadow_visibility(u_shadow_map2, 2, v_world);
#endif
#if SHADOWS > 3
    vis[3] = shadow_visibility(u_shadow_map3, 3, v_world);
#endif
}
// SHADING 4: N . H (Blinn-Phong); 7: R . V (Phong)
float specular_factor(vec3 n, vec3 l, vec3 v) {
#if SHADING == 7
    float x = max(0.0, dot(reflect(-l, n), v));
#else
    float x = max(0.0, dot(n, normalize(l + v)));
#endif
    return u_shininess == 0.0 ? 1.0 : pow(x, u_shininess);
}
void main() {
#if SHADING == 6
    frag = vec4(vec3(gl_FragCoord.z), 1.0);
#elif SHADING == 5
    frag = vec4(0.5 * normalize(v_normal) + 0.5, 1.0);
#else
    vec4 base = u_color * v_color;
#if TEXTURED
    base *= texture(u_texture, v_uv);
#endif
#if SHADING == 0
    frag = base;
#elif SHADING == 8
    float metallic = u_metallic, roughness = u_roughness, occlusion = 1.0;
    vec3 emissive = u_emissive;
#if MR_MAP
    vec4 mr = texture(u_mr_texture, v_uv);
    roughness *= mr.g;
    metallic *= mr.b;
#endif
#if OCCLUSION_MAP
    occlusion = 1.0 + u_occlusion_strength * (texture(u_occlusion_texture, v_uv).r - 1.0);
#endif
#if EMISSIVE_MAP
    emissive *= texture(u_emissive_texture, v_uv).rgb;
#endif
    float a = max(0.03, roughness) * max(0.03, roughness), a2 = a * a;
    vec3 c_diff = base.rgb * (1.0 - metallic), f0 = mix(vec3(0.04), base.rgb, metallic);
    vec3 n = normalize(v_normal), v = normalize(u_eye - v_world);
#if NORMAL_MAP
    // MikkTSpace's pixel-shader form: N and T as interpolated, B = w cross(N, T).
    vec3 m = texture(u_normal_texture, v_uv).rgb * 2.0 - 1.0;
    m.xy *= u_normal_scale;
    vec3 b = v_tangent.w * cross(v_normal, v_tangent.xyz);
    n = normalize(m.x * v_tangent.xyz + m.y * b + m.z * v_normal);
#endif
    float nv = max(0.0, dot(n, v));
    shadow_visibilities();
    vec3 rgb = u_ambient * c_diff * occlusion;
    for (int i = 0; i < LIGHTS; ++i) rgb += (u_light_color[i] * vis[u_shadow_of[i]]) * pbr_light(c_diff, f0, a2, n, v, u_to_light[i], nv);
#if POSITIONAL > 0
    for (int i = 0; i < POSITIONAL; ++i) {
        vec3 l;
        vec3 c = positional_light(i, v_world, l) * vis[u_pl_shadow[i]];
        rgb += c * pbr_light(c_diff, f0, a2, n, v, l, nv);
    }
#endif
#if ENVIRONMENT
    rgb += environment_light(c_diff, f0, n, v, nv, max(0.03, roughness), occlusion);
#endif
    frag = vec4(rgb + emissive, base.a);
#elif SHADING == 2
    frag = vec4(base.rgb * v_intensity, base.a);
#else
    vec3 n = normalize(v_normal);
    vec3 intensity = u_ambient;
    vec3 spec = vec3(0.0);
    vec3 v = normalize(u_eye - v_world);
    shadow_visibilities();
    for (int i = 0; i < LIGHTS; ++i) {
        float nl = dot(n, u_to_light[i]);
        vec3 c = u_light_color[i] * vis[u_shadow_of[i]];
        intensity += c * max(0.0, nl);
#if SHADING == 4 || SHADING == 7
        if (nl > 0.0) spec += c * u_specular * specular_factor(n, u_to_light[i], v);
#endif
    }
#if POSITIONAL > 0
    for (int i = 0; i < POSITIONAL; ++i) {
        vec3 l;
        vec3 c = positional_light(i, v_world, l) * vis[u_pl_shadow[i]];
        float nl = dot(n, l);
        intensity += c * max(0.0, nl);
#if SHADING == 4 || SHADING == 7
        if (nl > 0.0) spec += c * u_specular * specular_factor(n, l, v);
#endif
    }
#endif
    frag = vec4(base.rgb * intensity + spec, base.a);
#endif
#if TONE_MAPPING
    // TONE_CURVE: 0 none, 1 Reinhard, 2 ACES (Narkowicz's fit)
    vec3 x = u_exposure * frag.rgb;
#if TONE_CURVE == 1
    x = x / (1.0 + x);
#elif TONE_CURVE == 2
    x = clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
#endif
    frag.rgb = x;
#endif
#endif
#if CUTOFF
    if (frag.a < u_alpha_cutoff) discard;
#endif
}
)";

// The depth pass: positions only, the same y flip as the scene's vertex shader.
const char* const kDepthVertexShader = R"(#version 330 core
layout(location = 0) in vec3 a_pos;
uniform mat4 u_mvp;
void main() {
    vec4 clip = u_mvp * vec4(a_pos, 1.0);
    gl_Position = vec4(clip.x, -clip.y, clip.z, clip.w);
}
)";
const char* const kDepthFragmentShader = R"(#version 330 core
void main() {}
)";

GLuint standalone_program(const char* vertex, const char* fragment, const char* what) {
    const GLuint program = glCreateProgram();
    for (const auto& [type, src] : {std::pair{GLenum(GL_VERTEX_SHADER), vertex}, std::pair{GLenum(GL_FRAGMENT_SHADER), fragment}}) {
        const GLuint s = glCreateShader(type);
        glShaderSource(s, 1, &src, nullptr);
        glCompileShader(s);
        glAttachShader(program, s);
        glDeleteShader(s);  // freed with the program
    }
    glLinkProgram(program);
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) throw std::runtime_error(std::string("GLSL link error (") + what + ")");
    return program;
}

}  // namespace glref

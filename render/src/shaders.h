#pragma once
// Private to cordgrasp::render: GLSL 3.30 core sources of the renderer's programs.

namespace cordgrasp::render_detail {

// Meshes: positions and normals in the mesh frame; lighting in view space.
inline constexpr const char* kMeshVertex = R"(#version 330 core
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
uniform mat4 u_model_view;
uniform mat3 u_normal_matrix;
uniform mat4 u_proj;
out vec3 v_pos;
out vec3 v_normal;
void main() {
  vec4 p = u_model_view * vec4(a_pos, 1.0);
  v_pos = p.xyz;
  v_normal = u_normal_matrix * a_normal;
  gl_Position = u_proj * p;
}
)";

// Two directional lights fixed to the camera (key upper left, fill lower right), a
// hemispherical ambient term and a small specular highlight; two-sided.
inline constexpr const char* kMeshFragment = R"(#version 330 core
in vec3 v_pos;
in vec3 v_normal;
uniform vec4 u_color;
uniform int u_shading;      // 0 smooth, 1 flat, 2 unlit
uniform bool u_ortho;
uniform vec3 u_up_view;     // world up in view space
out vec4 frag;
const vec3 kKey = normalize(vec3(-0.45, 0.65, 0.62));
const vec3 kFill = normalize(vec3(0.7, -0.25, 0.55));
void main() {
  if (u_shading == 2) { frag = u_color; return; }
  vec3 v = u_ortho ? vec3(0.0, 0.0, 1.0) : normalize(-v_pos);
  vec3 n = u_shading == 1 ? cross(dFdx(v_pos), dFdy(v_pos)) : v_normal;
  float len = length(n);
  n = len > 1e-20 ? n / len : v;
  if (dot(n, v) < 0.0) n = -n;
  float diffuse = 0.62 * max(dot(n, kKey), 0.0) + 0.32 * max(dot(n, kFill), 0.0);
  float ambient = mix(0.26, 0.40, 0.5 + 0.5 * dot(n, u_up_view));
  vec3 h = normalize(kKey + v);
  float c = max(dot(n, h), 0.0);
  float c2 = c * c, c4 = c2 * c2, c8 = c4 * c4, c16 = c8 * c8;
  float spec = 0.22 * c16 * c16 * c16;  // Blinn-Phong exponent 48 without pow()
  frag = vec4(u_color.rgb * (ambient + diffuse) + vec3(spec), u_color.a);
}
)";

// Thick lines: each segment is a quad expanded in screen space; vertices are pushed toward
// the camera by the line's half width so a line lying on a surface is not half buried.
inline constexpr const char* kLineVertex = R"(#version 330 core
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_other;
layout(location = 2) in float a_side;
uniform mat4 u_view;
uniform mat4 u_proj;
uniform vec2 u_viewport;       // [px]
uniform float u_half_width;    // [px]
uniform float u_px_scale;      // metres per pixel (ortho) or per pixel per metre of depth
uniform bool u_ortho;
vec4 lift(vec3 p) {
  vec4 q = u_view * vec4(p, 1.0);
  float m_per_px = u_ortho ? u_px_scale : u_px_scale * max(-q.z, 0.0);
  vec3 toward = u_ortho ? vec3(0.0, 0.0, 1.0) : normalize(-q.xyz);
  q.xyz += toward * (m_per_px * u_half_width);
  return q;
}
void main() {
  vec4 a = u_proj * lift(a_pos);
  vec4 b = u_proj * lift(a_other);
  vec2 sa = a.xy / a.w * u_viewport * 0.5;
  vec2 sb = b.xy / b.w * u_viewport * 0.5;
  vec2 d = sb - sa;
  float len = length(d);
  d = len > 1e-6 ? d / len : vec2(1.0, 0.0);
  vec2 offset = vec2(-d.y, d.x) * a_side * u_half_width;
  a.xy += offset * 2.0 / u_viewport * a.w;
  gl_Position = a;
}
)";

// Round joins and caps of thick lines: point sprites the size of the line width.
inline constexpr const char* kCapVertex = R"(#version 330 core
layout(location = 0) in vec3 a_pos;
uniform mat4 u_view;
uniform mat4 u_proj;
uniform float u_half_width;
uniform float u_px_scale;
uniform bool u_ortho;
void main() {
  vec4 q = u_view * vec4(a_pos, 1.0);
  float m_per_px = u_ortho ? u_px_scale : u_px_scale * max(-q.z, 0.0);
  vec3 toward = u_ortho ? vec3(0.0, 0.0, 1.0) : normalize(-q.xyz);
  q.xyz += toward * (m_per_px * u_half_width);
  gl_Position = u_proj * q;
  gl_PointSize = 2.0 * u_half_width;
}
)";

inline constexpr const char* kCapFragment = R"(#version 330 core
uniform vec4 u_color;
out vec4 frag;
void main() {
  if (length(gl_PointCoord - vec2(0.5)) > 0.5) discard;
  frag = u_color;
}
)";

inline constexpr const char* kFlatFragment = R"(#version 330 core
uniform vec4 u_color;
out vec4 frag;
void main() { frag = u_color; }
)";

// Shadow mask: seen from below the floor, the lowest surface wins the depth test; its
// intensity falls off with height above the floor.
inline constexpr const char* kShadowVertex = R"(#version 330 core
layout(location = 0) in vec3 a_pos;
uniform mat4 u_model;
uniform mat4 u_view_proj;
uniform vec3 u_up;
uniform float u_floor;
out float v_height;
void main() {
  vec4 p = u_model * vec4(a_pos, 1.0);
  v_height = dot(p.xyz, u_up) - u_floor;
  gl_Position = u_view_proj * p;
}
)";

inline constexpr const char* kShadowFragment = R"(#version 330 core
in float v_height;
uniform float u_falloff;   // [m]
out vec4 frag;
void main() {
  float s = exp(-max(v_height, 0.0) / u_falloff);
  frag = vec4(s, s, s, 1.0);
}
)";

// The floor quad: darkens the background by the blurred shadow mask.
inline constexpr const char* kGroundVertex = R"(#version 330 core
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec2 a_uv;
uniform mat4 u_view_proj;
out vec2 v_uv;
void main() {
  v_uv = a_uv;
  gl_Position = u_view_proj * vec4(a_pos, 1.0);
}
)";

inline constexpr const char* kGroundFragment = R"(#version 330 core
in vec2 v_uv;
uniform sampler2D u_mask;
uniform float u_strength;
out vec4 frag;
void main() { frag = vec4(0.0, 0.0, 0.0, u_strength * texture(u_mask, v_uv).r); }
)";

// Supersampling resolve: box filter over s×s texels, averaged in (approximately) linear
// light: gamma 2 (square, mean, square root) is close to sRGB and far cheaper than pow().
inline constexpr const char* kResolveVertex = R"(#version 330 core
void main() {
  vec2 p = vec2((gl_VertexID == 1) ? 3.0 : -1.0, (gl_VertexID == 2) ? 3.0 : -1.0);
  gl_Position = vec4(p, 0.0, 1.0);
}
)";

inline constexpr const char* kResolveFragment = R"(#version 330 core
uniform sampler2D u_image;
uniform int u_factor;
out vec4 frag;
void main() {
  ivec2 origin = ivec2(gl_FragCoord.xy) * u_factor;
  vec3 sum = vec3(0.0);
  for (int j = 0; j < u_factor; ++j)
    for (int i = 0; i < u_factor; ++i) {
      vec3 c = texelFetch(u_image, origin + ivec2(i, j), 0).rgb;
      sum += c * c;
    }
  frag = vec4(sqrt(sum / float(u_factor * u_factor)), 1.0);
}
)";

}  // namespace cordgrasp::render_detail

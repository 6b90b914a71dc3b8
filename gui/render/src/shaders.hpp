// Private: GLSL 3.30 core sources of the scene, bar, overlay and text programs.
#pragma once

namespace styk::render::shaders {

inline constexpr const char* kSceneVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;
layout(location = 3) in float a_t;
uniform mat4 u_view;
uniform mat4 u_projection;
uniform float u_point_size;
centroid out vec3 v_normal;
centroid out vec3 v_color;
centroid out float v_t;
void main() {
  v_normal = mat3(u_view) * a_normal;
  v_color = a_color;
  v_t = a_t;
  gl_PointSize = u_point_size;
  gl_Position = u_projection * u_view * vec4(a_position, 1.0);
}
)";

// Contours are coloured per fragment from the interpolated scale position t, so band limits are
// sharp and exact whatever the triangle size. With multisampling the values are taken at the
// centroid of the covered samples (never extrapolated beyond the triangle: t = 0 at an edge must
// not turn into t < 0, "no field"). The light sits just above-left of the eye, so faces
// of an isometric view get different shades; a face seen square-on still gets exactly its colour
// (the factor saturates at 1 there), which keeps band colours countable.
inline constexpr const char* kSceneFragment = R"(#version 330 core
centroid in vec3 v_normal;
centroid in vec3 v_color;
centroid in float v_t;
uniform bool u_lit;
uniform bool u_use_field;
uniform bool u_smooth;
uniform int u_bands;
uniform vec3 u_palette[24];
uniform bool u_use_override;
uniform vec3 u_override;
uniform float u_line_shade;
uniform bool u_round_points;
out vec4 frag_color;
vec3 rainbow(float t) {
  float hue = 4.0 * (1.0 - clamp(t, 0.0, 1.0));
  int sextant = min(int(hue), 3);
  float f = hue - float(sextant);
  if (sextant == 0) return vec3(1.0, f, 0.0);
  if (sextant == 1) return vec3(1.0 - f, 1.0, 0.0);
  if (sextant == 2) return vec3(0.0, 1.0, f);
  return vec3(0.0, 1.0 - f, 1.0);
}
void main() {
  if (u_round_points && length(gl_PointCoord - vec2(0.5)) > 0.5) discard;
  vec3 c = v_color * u_line_shade;
  if (u_use_field && v_t > -0.5) {  // no field: t = -1 at every vertex
    float t = clamp(v_t, 0.0, 1.0);
    if (u_smooth) {
      c = rainbow(t);
    } else {
      c = u_palette[min(int(floor(t * float(u_bands))), u_bands - 1)];
    }
  }
  if (u_use_override) c = u_override;
  if (u_lit) {
    const vec3 light = normalize(vec3(-0.3, 0.5, 1.0));
    float facing = abs(dot(normalize(v_normal), light));
    c *= min(1.0, 0.55 + 0.6 * facing);
  }
  frag_color = vec4(c, 1.0);
}
)";

// Line elements: the scene's vertex stage with outputs for a geometry stage that widens each
// segment into a screen-space quad of u_line_width pixels (core profile GL draws wide GL_LINES
// only up to 1 px on some drivers), with square caps so the segments of a 3-node line join. The
// quad keeps the depth of its segment, so solids in front hide it. The scene's fragment stage
// colours it (unlit: layer colour or contour colour per pixel).
inline constexpr const char* kBarVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec3 a_color;
layout(location = 3) in float a_t;
uniform mat4 u_view;
uniform mat4 u_projection;
out vec3 g_color;
out float g_t;
void main() {
  g_color = a_color;
  g_t = a_t;
  gl_Position = u_projection * u_view * vec4(a_position, 1.0);
}
)";

inline constexpr const char* kBarGeometry = R"(#version 330 core
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
in vec3 g_color[];
in float g_t[];
uniform vec2 u_viewport;
uniform float u_line_width;
centroid out vec3 v_normal;
centroid out vec3 v_color;
centroid out float v_t;
void corner(int end, vec2 offset_pixels) {
  vec4 p = gl_in[end].gl_Position;
  gl_Position = vec4(p.xy + offset_pixels * 2.0 / u_viewport * p.w, p.zw);
  v_normal = vec3(0.0);
  v_color = g_color[end];
  v_t = g_t[end];
  EmitVertex();
}
void main() {
  vec4 a = gl_in[0].gl_Position, b = gl_in[1].gl_Position;
  if (a.w <= 0.0 || b.w <= 0.0) return;
  vec2 d = (b.xy / b.w - a.xy / a.w) * 0.5 * u_viewport;
  float len = length(d);
  vec2 along = len > 1e-6 ? d / len : vec2(1.0, 0.0);
  vec2 across = vec2(-along.y, along.x) * 0.5 * u_line_width;
  along *= 0.5 * u_line_width;
  corner(0, -along + across);
  corner(0, -along - across);
  corner(1, along + across);
  corner(1, along - across);
  EndPrimitive();
}
)";

inline constexpr const char* kOverlayVertex = R"(#version 330 core
layout(location = 0) in vec2 a_position;
layout(location = 1) in vec3 a_color;
uniform vec2 u_size;
out vec3 v_color;
void main() {
  v_color = a_color;
  gl_Position = vec4(2.0 * a_position.x / u_size.x - 1.0, 1.0 - 2.0 * a_position.y / u_size.y, 0.0, 1.0);
}
)";

inline constexpr const char* kOverlayFragment = R"(#version 330 core
in vec3 v_color;
out vec4 frag_color;
void main() { frag_color = vec4(v_color, 1.0); }
)";

// Text: glyph quads in pixels, their coverage fetched texel by texel from the atlas (u, v in
// texels: the quads lie on whole pixels, so every pixel centre meets one texel centre) and
// blended over the picture.
inline constexpr const char* kTextVertex = R"(#version 330 core
layout(location = 0) in vec2 a_position;
layout(location = 1) in vec2 a_texel;
layout(location = 2) in vec3 a_color;
uniform vec2 u_size;
out vec2 v_texel;
out vec3 v_color;
void main() {
  v_texel = a_texel;
  v_color = a_color;
  gl_Position = vec4(2.0 * a_position.x / u_size.x - 1.0, 1.0 - 2.0 * a_position.y / u_size.y, 0.0, 1.0);
}
)";

inline constexpr const char* kTextFragment = R"(#version 330 core
in vec2 v_texel;
in vec3 v_color;
uniform sampler2D u_atlas;
out vec4 frag_color;
void main() {
  float coverage = texelFetch(u_atlas, ivec2(floor(v_texel)), 0).r;
  frag_color = vec4(v_color, coverage);
}
)";

}  // namespace styk::render::shaders

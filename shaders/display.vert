#version 330 core
// One triangle that covers the viewport; no vertex buffer (draw 3 vertices with an empty VAO).
// v_uv runs 0..1 left to right and top to bottom, so texture row 0 (the image's top row, as the
// core stores it) lands at the top of the target.
out vec2 v_uv;

void main() {
  vec2 ndc = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2)) * 2.0 - 1.0;
  v_uv = vec2(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5);
  gl_Position = vec4(ndc, 0.0, 1.0);
}

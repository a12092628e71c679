// raster_sky.vert: one triangle covering the whole image (the environment seen where primary
// rays hit nothing, raster_sky.frag); drawn first, without depth.
void main() {
  vec2 corner = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
  gl_Position = vec4(corner, 1.0, 1.0);
}

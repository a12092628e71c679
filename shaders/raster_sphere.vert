// raster_sphere.vert: the box around one sphere, whose fragments raster_sphere.frag turns into
// the exact sphere by casting a ray (an impostor). Culling is off: from inside the box its far
// faces still cover every direction the sphere is in.
layout(location = 0) in vec3 gloss_in_corner;  // a corner of the cube [-1, 1]^3
uniform vec3 gloss_sphere_centre;
uniform float gloss_sphere_radius;
out vec3 gloss_position;
void main() {
  // 1 % larger than the sphere: a float rounding must not shave a silhouette pixel off.
  gloss_position = gloss_sphere_centre + 1.01 * gloss_sphere_radius * gloss_in_corner;
  gl_Position = gloss_project(gloss_position);
}

#pragma once
// The environment's specular term for the reference path's images (reference's own): the lobe's
// mean of L by the midpoint rule over a grid s times finer than the map's texels, walked only
// within the lobe's reach, s from the exponent (parts no wider than 0.049 / sqrt(alpha + 1)
// radians, so the rule's error, (width^2 / 24) (alpha + 1) relative, stays near 1e-4), and four
// times finer again where the horizon crosses a part. The reach leaves out at most 1e-6 of the
// lobe's weight. About 10^4 to 10^5 evaluations per pixel whatever alpha, against 10^5 cells of
// environment_quadrature.h's bounded cubature at the presets' exponents on a bright map: the
// pixel inspector and the tests use that one; tests/reference checks the two agree.
#include <glm/vec3.hpp>

#include "base/image.h"
#include "reference/quadrature_cells.h"

namespace gloss {

// integral of L lobe / integral of lobe over the map (intensity 1), lobe in the map's frame,
// mirror the lobe's centre direction (r for both models: Blinn-Phong's lobe lies about r too).
glm::dvec3 lobe_mean(const Image& map, const quadrature::Lobe& lobe, const glm::dvec3& mirror);

}  // namespace gloss

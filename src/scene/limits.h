#pragma once
// Bounds on a scene's numbers that keep the renderer's float arithmetic finite
// (docs/spec/scene-and-cli.md, "Numeric limits").
namespace gloss {

// |x| of every coordinate (camera eye, target and up, light positions, sphere centres and radii,
// mesh vertices after placement), world units. The renderer works in float (largest 3.4e38):
// a difference of two coordinates is at most 2e15, the squared length of such a vector at most
// 3 * 4e30 = 1.2e31, and ray-sphere and attenuation products of two such terms stay below 1e38.
// Past about 1.84e19 (the square root of the largest float) a squared distance is infinite.
constexpr double kMaxCoordinate = 1e15;

}  // namespace gloss

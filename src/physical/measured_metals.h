#pragma once
// Normal-incidence reflectance F0 of the physical reference's materials
// (docs/spec/physical-reference.md). The metals' values are measured: linear sRGB, from
// Real-Time Rendering, 4th edition (Akenine-Moller, Haines, Hoffman et al., 2018), Table 9.2;
// other tables differ by up to 0.09 in G and B, so every place that shows them names the source
// (kMeasuredF0Source). Compiled in rather than read from assets/: they are part of the reference's
// definition, like the dielectric's 0.04, and the kinds they belong to are a closed set of names
// of the scene format (scene/physical_reference.h).
#include <glm/vec3.hpp>

#include "scene/physical_reference.h"

namespace gloss {

inline constexpr const char* kMeasuredF0Source = "Real-Time Rendering, 4th ed., Table 9.2";

// A dielectric's F0 (index of refraction 1.5: ((1.5 - 1) / (1.5 + 1))^2 = 0.04), every channel.
inline constexpr double kDielectricF0 = 0.04;

// F0 of a kind: the table's row for a metal, 0.04 grey for a dielectric.
glm::dvec3 reference_f0(ReferenceKind kind);

}  // namespace gloss

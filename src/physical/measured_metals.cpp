#include "physical/measured_metals.h"

namespace gloss {

glm::dvec3 reference_f0(ReferenceKind kind) {
  // Real-Time Rendering, 4th ed., Table 9.2 (linear sRGB), as docs/spec/physical-reference.md
  // lists it.
  switch (kind) {
    case ReferenceKind::gold:
      return {1.000, 0.782, 0.344};
    case ReferenceKind::silver:
      return {0.972, 0.960, 0.915};
    case ReferenceKind::aluminium:
      return {0.913, 0.922, 0.924};
    case ReferenceKind::copper:
      return {0.955, 0.638, 0.538};
    case ReferenceKind::chromium:
      return {0.549, 0.556, 0.554};
    case ReferenceKind::brass:
      return {0.910, 0.778, 0.423};
    case ReferenceKind::dielectric:
      break;
  }
  return glm::dvec3(kDielectricF0);
}

}  // namespace gloss

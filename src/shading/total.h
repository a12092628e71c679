#pragma once
// The one place a pixel's total is formed from its terms (spec: total = emissive + ambient +
// sum of diffuse + sum of specular, plus the background where primary rays missed), in one
// fixed order so every path that forms it (the scalar recombination, the 16-lane total of the
// first pass, the extra materials of mixed pixels, the double-precision reference) gets the
// same bits for the same inputs:
//
//   total = (((emissive + ambient) + diffuse) + specular) + missed share x background
//
// T is float, double, or a glm vector of either; the lane loops call it per lane.
namespace gloss {

// The sum of a material's four terms alone (the further materials of a mixed pixel are added
// to its total this way).
template <class T>
inline T form_total(const T& emissive, const T& ambient, const T& diffuse, const T& specular) {
  return ((emissive + ambient) + diffuse) + specular;
}

template <class T>
inline T form_total(const T& emissive, const T& ambient, const T& diffuse, const T& specular,
                    const T& missed_background) {
  return form_total(emissive, ambient, diffuse, specular) + missed_background;
}

}  // namespace gloss

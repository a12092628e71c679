#include "base/image.h"

namespace gloss {

const char* to_string(Term term) {
  switch (term) {
    case Term::emissive:
      return "emissive";
    case Term::ambient:
      return "ambient";
    case Term::diffuse:
      return "diffuse";
    case Term::specular:
      return "specular";
    case Term::total:
      return "total";
  }
  return "total";
}

const Image& term_image(const TermImages& terms, Term term) {
  switch (term) {
    case Term::emissive:
      return terms.emissive;
    case Term::ambient:
      return terms.ambient;
    case Term::diffuse:
      return terms.diffuse;
    case Term::specular:
      return terms.specular;
    case Term::total:
      return terms.total;
  }
  return terms.total;
}

}  // namespace gloss

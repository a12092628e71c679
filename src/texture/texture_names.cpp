#include "texture/texture_lookup.h"

namespace gloss {

const char* to_string(Wrap wrap) {
  switch (wrap) {
    case Wrap::repeat:
      return "repeat";
    case Wrap::clamp:
      return "clamp";
    case Wrap::mirror:
      return "mirror";
  }
  return "?";
}

const char* to_string(MapFilter filter) {
  switch (filter) {
    case MapFilter::trilinear:
      return "trilinear";
    case MapFilter::bilinear:
      return "bilinear";
    case MapFilter::nearest:
      return "nearest";
  }
  return "?";
}

}  // namespace gloss

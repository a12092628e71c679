#include "scene/physical_reference.h"

#include <cstring>

namespace gloss {

namespace {

constexpr const char* kNames[kReferenceKinds] = {"gold",     "silver", "aluminium", "copper",
                                                 "chromium", "brass",  "dielectric"};

}  // namespace

const char* to_string(ReferenceKind kind) {
  const int i = static_cast<int>(kind);
  return i >= 0 && i < kReferenceKinds ? kNames[i] : "?";
}

bool parse_reference_kind(const char* name, ReferenceKind& kind) {
  for (int i = 0; i < kReferenceKinds; ++i) {
    if (std::strcmp(name, kNames[i]) == 0) {
      kind = static_cast<ReferenceKind>(i);
      return true;
    }
  }
  return false;
}

}  // namespace gloss

#pragma once
// What the user has selected. Not part of the document (not undone, not saved but in the
// recovery file): panels, the viewport's clicks and scripts' `select` set it directly.
#include <algorithm>
#include <vector>

namespace gloss {

struct Selection {
  int object = 0;           // the primary object (the Material panel's); readers clamp it
  std::vector<int> others;  // further selected objects (Ctrl/Shift+click, a model's parts)
  int light = 0;            // index into scene.lights; likewise clamped
};

// Every selected object of a scene with count objects, ascending, each once; the primary is
// clamped in, others out of range are left out. Empty for an empty scene.
inline std::vector<int> selected_objects(const Selection& s, int count) {
  std::vector<int> out;
  if (count <= 0) return out;
  out.push_back(std::clamp(s.object, 0, count - 1));
  for (int i : s.others) {
    if (i >= 0 && i < count) out.push_back(i);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

inline void select_only(Selection& s, int object) {
  s.object = object;
  s.others.clear();
}

// objects selected, the first of them primary; nothing changes for an empty list.
inline void select_all_of(Selection& s, const std::vector<int>& objects) {
  if (objects.empty()) return;
  s.object = objects.front();
  s.others.assign(objects.begin() + 1, objects.end());
}

}  // namespace gloss

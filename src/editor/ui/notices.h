#pragma once
// Short messages shown over the top-right corner of the viewport: saved files (with their path),
// errors from panels and dialogs. Each stays for a few seconds; errors stay longer. The top
// right, because the pixel inspector, the term sheet's total sit at the bottom, where they were
// covered; in the lobe view, whose controls are at the top, the bottom right.
#include <string>
#include <vector>

namespace gloss {

struct Notice {
  std::string text;
  bool error = false;
  double until_s = 0.0;  // frame-clock time at which it disappears
};

struct Notices {
  std::vector<Notice> items;  // oldest first
  std::string last;           // the newest text, also shown in the status bar

  void info(const std::string& text, double now_s);
  void error(const std::string& text, double now_s);
  // Drops expired notices; returns seconds until the next expiry (for the event-loop timeout),
  // or a negative value when none is shown.
  double expire(double now_s);
  // Draws the notices right-aligned at `right`, stacked down from y (from_top) or up from it
  // (screen coordinates).
  void draw(float right, float y, bool from_top) const;
};

}  // namespace gloss

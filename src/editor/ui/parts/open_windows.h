#pragma once
// Which of the editor's floating windows and questions are open. The side panels and the
// viewport are always drawn; the pixel inspector's switch is a view setting (view_settings.h,
// scripts set it). Menus, shortcuts and the windows' own close buttons change these.

namespace gloss {

struct OpenWindows {
  bool help = false;           // the help window (F1)
  bool quality = false;        // the Quality window
  bool quit_question = false;  // the unsaved-changes question before quitting
};

}  // namespace gloss

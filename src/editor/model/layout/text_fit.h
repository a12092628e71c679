#pragma once
// Text cut to a width, for lines that must not push what follows them off the window (the
// status bar's message): the start and the end are kept around "...", so a saved file's name
// (at the end of its path) and what happened (at the start) both stay.
#include <functional>
#include <string>

namespace gloss {

// How wide a text is drawn, in pixels (ImGui::CalcTextSize in the editor).
using TextWidth = std::function<float(const std::string&)>;

// text when it fits in max_width; else its start, "...", and its end, as much of each as fits
// (the end getting at least a third of the room); "" when not even "..." fits. Cuts only between
// UTF-8 characters.
std::string fit_text(const std::string& text, float max_width, const TextWidth& width);

}  // namespace gloss

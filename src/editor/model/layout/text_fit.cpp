#include "editor/model/layout/text_fit.h"

#include <vector>

namespace gloss {

namespace {

// Byte offsets where UTF-8 characters start, and the text's end.
std::vector<std::size_t> character_starts(const std::string& text) {
  std::vector<std::size_t> starts;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) starts.push_back(i);
  }
  starts.push_back(text.size());
  return starts;
}

}  // namespace

std::string fit_text(const std::string& text, float max_width, const TextWidth& width) {
  if (width(text) <= max_width) return text;
  const std::string dots = "...";
  if (width(dots) > max_width) return "";
  const std::vector<std::size_t> at = character_starts(text);
  const std::size_t n = at.size() - 1;  // characters
  // Characters kept from the end: the most that fit in a third of the room beside the dots.
  const float room = max_width - width(dots);
  std::size_t tail = 0;
  while (tail < n && width(text.substr(at[n - tail - 1])) <= room / 3.0f) ++tail;
  const std::string end = text.substr(at[n - tail]);
  // Then as many from the start as fit with it.
  std::size_t head = 0;
  while (head < n - tail && width(text.substr(0, at[head + 1]) + dots + end) <= max_width) {
    ++head;
  }
  return text.substr(0, at[head]) + dots + end;
}

}  // namespace gloss

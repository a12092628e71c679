#include "base/text/printable_text.h"

namespace gloss {

namespace {

bool is_continuation(unsigned char byte) {
  return (byte & 0xC0u) == 0x80u;
}

}  // namespace

void append_hex_escape(std::string& out, unsigned char byte) {
  const char* const digits = "0123456789ABCDEF";
  out += "\\x";
  out += digits[byte >> 4];
  out += digits[byte & 0x0Fu];
}

std::size_t utf8_sequence_length(const std::string& text, std::size_t i) {
  const std::size_t left = text.size() - i;
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[i + k]); };
  const unsigned char lead = byte(0);
  if (lead < 0x80u) return 1;
  std::size_t length = 0;
  unsigned char lo = 0x80u, hi = 0xBFu;  // the range of the second byte (Table 3-7)
  if (lead >= 0xC2u && lead <= 0xDFu) {
    length = 2;
  } else if (lead >= 0xE0u && lead <= 0xEFu) {
    length = 3;
    if (lead == 0xE0u) lo = 0xA0u;  // no overlong forms
    if (lead == 0xEDu) hi = 0x9Fu;  // no surrogates U+D800-U+DFFF
  } else if (lead >= 0xF0u && lead <= 0xF4u) {
    length = 4;
    if (lead == 0xF0u) lo = 0x90u;  // no overlong forms
    if (lead == 0xF4u) hi = 0x8Fu;  // nothing above U+10FFFF
  } else {
    return 0;  // a continuation byte, C0, C1 or F5-FF
  }
  if (left < length || byte(1) < lo || byte(1) > hi) return 0;
  for (std::size_t k = 2; k < length; ++k) {
    if (!is_continuation(byte(k))) return 0;
  }
  return length;
}

std::string printable_text(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    const auto lead = static_cast<unsigned char>(text[i]);
    const std::size_t length = utf8_sequence_length(text, i);
    const bool c0_or_del = length == 1 && (lead < 0x20u || lead == 0x7Fu);
    const bool c1 = length == 2 && lead == 0xC2u && static_cast<unsigned char>(text[i + 1]) < 0xA0u;
    if (length == 0 || c0_or_del) {
      append_hex_escape(out, lead);
      ++i;
    } else if (c1) {
      append_hex_escape(out, lead);
      append_hex_escape(out, static_cast<unsigned char>(text[i + 1]));
      i += 2;
    } else {
      out.append(text, i, length);
      i += length;
    }
  }
  return out;
}

}  // namespace gloss

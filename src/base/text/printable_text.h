#pragma once
// Text from input files (names, paths, tokens) shown to a person: nothing in it may drive the
// terminal. Also the UTF-8 test that the name escape of io/json/name_escape.h is built on.
#include <cstddef>
#include <string>

namespace gloss {

// The length (1 to 4) of the well-formed UTF-8 sequence that starts at text[i], or 0 when the
// bytes there are not one (a stray continuation byte, an overlong form, a surrogate, a code
// point above U+10FFFF, a truncated sequence). RFC 3629, Table 3-7 of the Unicode standard.
std::size_t utf8_sequence_length(const std::string& text, std::size_t i);

// Appends byte as \xHH (two uppercase hex digits), the escape of printable_text and of
// io/json/name_escape.h alike.
void append_hex_escape(std::string& out, unsigned char byte);

// text with every byte that could reach a terminal as a control written as \xHH (two uppercase
// hex digits): C0 controls (0x00-0x1F, including \n, \r, \t and ESC), DEL (0x7F), the C1
// controls U+0080-U+009F (UTF-8 C2 80 to C2 9F, which some terminals obey) and every byte that
// is not part of well-formed UTF-8. Everything else, backslashes included, is kept as is: this
// is for reading, not for reading back.
std::string printable_text(const std::string& text);

}  // namespace gloss

#pragma once
// JSON parsing with error positions people can read: nlohmann reports a byte offset, editors show
// line:column. Shared by every loader of gloss's JSON files (scenes, materials).
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

namespace gloss {

// The 1-based line and column of the byte at offset in text. Lines end at '\n'; columns count
// UTF-8 characters (a tab is one column). An offset past the end gives the position just after
// the last character.
void byte_offset_to_line_column(const std::string& text, std::size_t offset, int& line,
                                int& column);

// Parses text as JSON; on a syntax error or truncated text throws InputError(file, message, line,
// column) of the last character the parser read: the offending character, or the end of the
// offending token (a misplaced string is reported at its closing quote). Truncated text is
// reported just past its end. Any other exception of the JSON library (a number such as 1e400
// that overflows a double) is an InputError too, at the offending token. Object keys come out
// sorted.
nlohmann::json parse_json_text(const std::string& text, const std::string& file);

// As parse_json_text, but objects keep the file's key order (for lists the user arranged).
nlohmann::ordered_json parse_ordered_json_text(const std::string& text, const std::string& file);

}  // namespace gloss

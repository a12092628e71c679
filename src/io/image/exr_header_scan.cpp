// scan_exr_header (exr_header_scan.h). The layout (openexr.com, "OpenEXR File Layout"): the magic
// number 76 2f 31 01, a 4-byte version field (the format version, 2, in its low byte; flags
// above), then each part's header: attributes (name\0, type name\0, int32 value size, the value)
// up to an empty name; a multi-part file ends its list of headers with an empty header. Then one
// chunk offset table per part (8 bytes a chunk), then the chunks. Numbers are little-endian.
#include "io/image/exr_header_scan.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>

#include "base/error.h"

namespace gloss {

namespace {

constexpr std::uint32_t kTiledFlag = 0x200;
constexpr std::uint32_t kLongNamesFlag = 0x400;
constexpr std::uint32_t kDeepFlag = 0x800;  // "non-image": deep data
constexpr std::uint32_t kMultiPartFlag = 0x1000;
constexpr int kMaxNameLength = 255;  // Imf::Name::MAX_LENGTH: OpenEXR reads no longer name
constexpr int kMaxTileSide = 32768;  // what read_exr_image sets as OpenEXR's largest tile
constexpr int kZipCompression = 3;   // OpenEXR's default header has ZIP

// The size OpenEXR 3.1 reads for a value of a known fixed-size type, whatever size the file
// declares (Imf::TypedAttribute<T>::readValueFrom reads T's fields); 0 for other types. A
// declared size that differs would leave the library reading the next attribute from elsewhere
// than this walk does.
int fixed_value_size(const std::string& type) {
  static const struct {
    const char* type;
    int bytes;
  } kTypes[] = {{"box2i", 16},
                {"box2f", 16},
                {"chromaticities", 32},
                {"compression", 1},
                {"deepImageState", 1},
                {"double", 8},
                {"envmap", 1},
                {"float", 4},
                {"int", 4},
                {"keycode", 28},
                {"lineOrder", 1},
                {"m33f", 36},
                {"m33d", 72},
                {"m44f", 64},
                {"m44d", 128},
                {"rational", 8},
                {"tiledesc", 9},
                {"timecode", 8},
                {"v2i", 8},
                {"v2f", 8},
                {"v2d", 16},
                {"v3i", 12},
                {"v3f", 12},
                {"v3d", 24}};
  for (const auto& t : kTypes) {
    if (type == t.type) return t.bytes;
  }
  return 0;
}

// Scan lines in one chunk for each compression (Imf::numLinesInBuffer); the most, 256, for an
// unknown one (the library refuses it later; until then this over-counts memory and under-counts
// chunks, both on the safe side).
int lines_per_chunk(int compression) {
  static const int kLines[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};
  return compression >= 0 && compression < 10 ? kLines[compression] : 256;
}

std::int32_t int32_at(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
  return static_cast<std::int32_t>(v);
}

// A name from the file as errors show it: names are up to 255 bytes of anything.
std::string shown(const std::string& name) {
  return name.size() <= 40 ? name : name.substr(0, 40) + "...";
}

std::uint64_t ceil_div(std::uint64_t a, std::uint64_t b) {
  return a / b + (a % b != 0 ? 1 : 0);
}

// Products and sums that stop at the largest uint64 instead of wrapping: a header's numbers are
// the file's to choose, and a wrapped estimate would pass any check.
std::uint64_t times(std::uint64_t a, std::uint64_t b) {
  return b != 0 && a > std::numeric_limits<std::uint64_t>::max() / b
             ? std::numeric_limits<std::uint64_t>::max()
             : a * b;
}
std::uint64_t plus(std::uint64_t a, std::uint64_t b) {
  return a > std::numeric_limits<std::uint64_t>::max() - b
             ? std::numeric_limits<std::uint64_t>::max()
             : a + b;
}

// What one part's header says about the part's size and layout.
struct Part {
  long long x0 = 0, y0 = 0, x1 = 63, y1 = 63;  // dataWindow
  int compression = kZipCompression;
  std::vector<std::string> channels;
  std::uint64_t bytes_per_pixel = 0;  // over every channel, as stored (HALF 2, UINT and FLOAT 4)
  bool has_tiles = false;
  std::uint32_t tile_width = 0, tile_height = 0;
  std::string type;  // the "type" attribute: scanlineimage, tiledimage, deepscanline, deeptile
  bool has_chunk_count = false;
  std::int32_t chunk_count = 0;
  bool empty = true;  // no attribute: the end of a multi-part file's headers

  long long width() const { return x1 - x0 + 1; }
  long long height() const { return y1 - y0 + 1; }
};

class HeaderReader {
 public:
  explicit HeaderReader(const std::string& path) : m_path(path), m_in(path, std::ios::binary) {
    if (!m_in) throw InputError(path, std::string("cannot read: ") + std::strerror(errno));
    m_in.seekg(0, std::ios::end);
    m_size = static_cast<std::uint64_t>(m_in.tellg());
    m_in.seekg(0);
  }

  std::uint64_t at() const { return m_at; }
  std::uint64_t size() const { return m_size; }
  std::uint64_t left() const { return m_size - m_at; }

  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(m_path, "invalid OpenEXR: " + message);
  }

  // n bytes (n <= left(), checked by the caller).
  std::string bytes(std::size_t n) {
    std::string out(n, '\0');
    if (n > 0 && !m_in.read(&out[0], static_cast<std::streamsize>(n))) fail("cannot read the file");
    m_at += n;
    return out;
  }

  void skip(std::uint64_t n) {
    m_at += n;
    m_in.seekg(static_cast<std::streamoff>(m_at));
  }

  // A NUL-terminated name of at most kMaxNameLength characters; what says what it is.
  std::string name(const std::string& what) {
    std::string out;
    const std::uint64_t start = m_at;
    for (;;) {
      if (left() == 0) {
        fail("the header does not end: the file ends inside " + what + " at byte " +
             std::to_string(start));
      }
      const char c = bytes(1)[0];
      if (c == '\0') return out;
      if (out.size() == kMaxNameLength) {
        fail(what + " at byte " + std::to_string(start) + " is longer than OpenEXR's " +
             std::to_string(kMaxNameLength) + " characters");
      }
      out.push_back(c);
    }
  }

  std::int32_t int32(const std::string& what) {
    if (left() < 4) fail("the file ends inside " + what + " at byte " + std::to_string(m_at));
    return int32_at(bytes(4), 0);
  }

 private:
  std::string m_path;
  std::ifstream m_in;
  std::uint64_t m_size = 0, m_at = 0;
};

// A chlist value (Imf::ChannelListAttribute): per channel its name\0, int32 pixel type, pLinear,
// three reserved bytes, int32 x and y sampling; an empty name ends it. OpenEXR reads up to that
// end whatever the declared size, so the two must agree.
void read_channel_list(const HeaderReader& reader, const std::string& described,
                       const std::string& value, Part& part) {
  const auto bad = [&](const std::string& why) { reader.fail(described + " " + why); };
  part.channels.clear();
  part.bytes_per_pixel = 0;
  std::size_t at = 0;
  for (;;) {
    const std::size_t end = value.find('\0', at);
    if (end == std::string::npos) bad("ends inside a channel name");
    if (end - at > kMaxNameLength) bad("has a channel name longer than 255 characters");
    if (end == at) break;
    if (value.size() - (end + 1) < 16) {
      bad("ends inside channel '" + shown(value.substr(at, end - at)) + "'");
    }
    part.channels.push_back(value.substr(at, end - at));
    part.bytes_per_pixel += int32_at(value, end + 1) == 1 ? 2 : 4;  // 1: HALF
    at = end + 1 + 16;
  }
  if (at + 1 != value.size()) {
    bad("declares " + std::to_string(value.size()) + " bytes but its list ends after " +
        std::to_string(at + 1));
  }
}

// A preview value (Imf::PreviewImageAttribute): uint32 width and height, then width x height
// RGBA pixels of 4 bytes, which the library allocates from the two numbers alone.
void check_preview(const HeaderReader& reader, const std::string& described,
                   const std::string& value) {
  if (value.size() < 8) reader.fail(described + " is shorter than its 8-byte size");
  const auto w = static_cast<std::uint32_t>(int32_at(value, 0));
  const auto h = static_cast<std::uint32_t>(int32_at(value, 4));
  const std::uint64_t needs = plus(8, times(times(w, h), 4));
  if (needs != value.size()) {
    reader.fail(described + " of " + std::to_string(w) + "x" + std::to_string(h) + " needs " +
                std::to_string(needs) + " bytes; it declares " + std::to_string(value.size()));
  }
}

// A stringvector value (Imf::StringVectorAttribute): strings, each an int32 length and its bytes,
// up to the declared size; the library sizes each string from its length before reading it.
void check_string_vector(const HeaderReader& reader, const std::string& described,
                         const std::string& value) {
  std::size_t at = 0;
  while (at < value.size()) {
    if (value.size() - at < 4) reader.fail(described + " ends inside a string's length");
    const std::int32_t length = int32_at(value, at);
    at += 4;
    if (length < 0 || static_cast<std::size_t>(length) > value.size() - at) {
      reader.fail(described + " holds a string of " + std::to_string(length) +
                  " bytes, more than " + std::to_string(value.size() - at) + " left in its value");
    }
    at += static_cast<std::size_t>(length);
  }
}

// One attribute: its name (empty: the end of the header), type, size and value.
bool read_attribute(HeaderReader& reader, Part& part) {
  const std::string name = reader.name("an attribute name");
  if (name.empty()) return false;
  part.empty = false;
  const std::string label = "attribute '" + shown(name) + "'";
  const std::string type = reader.name("the type name of " + label);
  const std::int32_t size = reader.int32("the value size of " + label);
  const std::string described = label + " (" + shown(type) + ")";
  if (size < 0) reader.fail(described + " declares a negative size (" + std::to_string(size) + ")");
  if (static_cast<std::uint64_t>(size) > reader.left()) {
    reader.fail(described + " declares " + std::to_string(size) + " bytes, more than the " +
                std::to_string(reader.left()) + " left in the file");
  }
  const int fixed = fixed_value_size(type);
  if (fixed > 0 && size != fixed) {
    reader.fail(described + " declares " + std::to_string(size) + " bytes; a " + type + " is " +
                std::to_string(fixed));
  }
  if (type == "floatvector" && size % 4 != 0) {
    reader.fail(described + " declares " + std::to_string(size) + " bytes, not whole floats");
  }
  if (type == "idmanifest") {
    // OpenEXR's versions disagree on this value's layout (4 or 8 bytes of size before the data).
    reader.fail(described + ": ID manifests are not read in maps");
  }
  // Types whose values OpenEXR reads by their content rather than by the declared size: a
  // chlist up to its empty name, a preview's width x height RGBA bytes, a stringvector's
  // length-prefixed strings. Any attribute of those types (not only the ones used here) is walked
  // as the library will walk it, or the library allocates what the content claims (a preview of
  // 65535 x 65535 is 17 GB) or reads the next attribute from elsewhere than this scan.
  if (type == "chlist" || type == "preview" || type == "stringvector") {
    const std::string value = reader.bytes(static_cast<std::size_t>(size));
    if (type == "chlist") {
      Part scratch;
      read_channel_list(reader, described, value, name == "channels" ? part : scratch);
    } else if (type == "preview") {
      check_preview(reader, described, value);
    } else {
      check_string_vector(reader, described, value);
    }
    return true;
  }
  const bool wanted =
      (name == "dataWindow" && type == "box2i") ||
      (name == "compression" && type == "compression") || (name == "tiles" && type == "tiledesc") ||
      (name == "type" && type == "string") || (name == "chunkCount" && type == "int");
  if (!wanted) {
    reader.skip(static_cast<std::uint64_t>(size));
    return true;
  }
  const std::string value = reader.bytes(static_cast<std::size_t>(size));
  if (name == "dataWindow") {
    part.x0 = int32_at(value, 0);
    part.y0 = int32_at(value, 4);
    part.x1 = int32_at(value, 8);
    part.y1 = int32_at(value, 12);
  } else if (name == "compression") {
    part.compression = static_cast<unsigned char>(value[0]);
  } else if (name == "tiles") {
    part.has_tiles = true;
    part.tile_width = static_cast<std::uint32_t>(int32_at(value, 0));
    part.tile_height = static_cast<std::uint32_t>(int32_at(value, 4));
  } else if (name == "type") {
    part.type = value;
  } else {
    part.has_chunk_count = true;
    part.chunk_count = int32_at(value, 0);
  }
  return true;
}

// The chunks of a part's offset table; for a tiled part those of its full-resolution level
// only, a lower bound (mipmap and ripmap levels add to it).
std::uint64_t chunk_table_entries(const HeaderReader& reader, const Part& part, bool tiled,
                                  bool multipart) {
  if (multipart && part.has_chunk_count) {
    if (part.chunk_count < 0) reader.fail("a part declares a negative chunkCount");
    return static_cast<std::uint64_t>(part.chunk_count);
  }
  if (part.width() < 1 || part.height() < 1) return 0;  // OpenEXR refuses the data window
  const auto width = static_cast<std::uint64_t>(part.width());
  const auto height = static_cast<std::uint64_t>(part.height());
  if (!tiled)
    return ceil_div(height, static_cast<std::uint64_t>(lines_per_chunk(part.compression)));
  return times(ceil_div(width, part.tile_width), ceil_div(height, part.tile_height));
}

bool part_is_tiled(const Part& part, bool multipart, std::uint32_t flags) {
  if (!multipart) return (flags & kTiledFlag) != 0;
  return part.type == "tiledimage" || part.type == "deeptile";
}

}  // namespace

ExrHeaderScan scan_exr_header(const std::string& path) {
  HeaderReader reader(path);
  if (reader.size() < 8) reader.fail("the file ends inside its magic number and version field");
  const std::string magic = reader.bytes(4);
  if (magic != std::string("\x76\x2f\x31\x01", 4)) reader.fail("not an OpenEXR file");
  const auto field = static_cast<std::uint32_t>(reader.int32("the version field"));
  const std::uint32_t flags = field & ~0xffu;
  if ((field & 0xff) != 2) {
    reader.fail("file format version " + std::to_string(field & 0xff) + " (gloss reads version 2)");
  }
  if ((flags & ~(kTiledFlag | kLongNamesFlag | kDeepFlag | kMultiPartFlag)) != 0) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%08x", static_cast<unsigned>(field));
    reader.fail(std::string("unknown flags in the version field (") + hex + ")");
  }
  const bool multipart = (flags & kMultiPartFlag) != 0;
  if (multipart && (flags & kTiledFlag) != 0) reader.fail("a multi-part file with the tiled flag");

  std::vector<Part> parts;
  for (;;) {
    Part part;
    while (read_attribute(reader, part)) {
    }
    if (multipart && part.empty) break;  // the empty header after the last part
    parts.push_back(part);
    if (!multipart) break;
  }
  if (parts.empty()) reader.fail("a multi-part file without a part");

  const Part& first = parts.front();
  const bool deep = multipart ? first.type.compare(0, 4, "deep") == 0 : (flags & kDeepFlag) != 0;
  if (deep) throw InputError(path, "OpenEXR deep images are not maps");

  std::uint64_t entries = 0;
  for (const Part& part : parts) {
    const bool tiled = part_is_tiled(part, multipart, flags);
    if (tiled && !part.has_tiles) reader.fail("a tiled part without a tile description ('tiles')");
    if (tiled && (part.tile_width < 1 || part.tile_width > kMaxTileSide || part.tile_height < 1 ||
                  part.tile_height > kMaxTileSide)) {
      reader.fail("tiles of " + std::to_string(part.tile_width) + "x" +
                  std::to_string(part.tile_height) + " pixels (OpenEXR's are 1 to " +
                  std::to_string(kMaxTileSide) + " a side here)");
    }
    entries = plus(entries, chunk_table_entries(reader, part, tiled, multipart));
  }
  if (entries > reader.left() / 8) {
    reader.fail("the file ends inside its chunk offset tables (" + std::to_string(entries) +
                " chunks need 8 bytes each after the headers, " + std::to_string(reader.left()) +
                " bytes are left)");
  }

  ExrHeaderScan scan;
  scan.width = first.width();
  scan.height = first.height();
  scan.channels = first.channels;
  scan.parts = static_cast<int>(parts.size());
  // The library's buffers for the first part: a chunk as read, plus the decompressor's input and
  // output (ZIP keeps two more copies, PIZ and DWA about as much): 4 chunks in all. A tiled part
  // read through Imf::InputFile also caches one row of tiles as floats (up to 4 channels). Then
  // the chunk tables and every attribute's value (the headers' bytes).
  const auto width = static_cast<std::uint64_t>(std::max(1LL, scan.width));
  std::uint64_t buffers = 0;
  if (part_is_tiled(first, multipart, flags)) {
    const std::uint64_t tile =
        times(times(first.tile_width, first.tile_height), first.bytes_per_pixel);
    buffers = plus(times(4, tile), times(times(width, first.tile_height), 4 * sizeof(float)));
  } else {
    const auto lines = static_cast<std::uint64_t>(lines_per_chunk(first.compression));
    buffers = times(4, times(times(width, first.bytes_per_pixel), lines));
  }
  // (At most 2^62: check_image_size adds the floats to it, and no budget is that large.)
  scan.library_bytes =
      std::min(plus(plus(buffers, times(entries, 8)), reader.at()), std::uint64_t(1) << 62);
  return scan;
}

}  // namespace gloss

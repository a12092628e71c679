#pragma once
// An OpenEXR file's headers walked by gloss before the OpenEXR library reads them (io's own,
// private). OpenEXR 3.1 allocates an attribute's value at the size the file declares before it
// reads a byte of it (1.6 GB from a 50-byte file), and sizes its line, tile and chunk-table
// buffers from the header alone. The walk refuses a header whose declared sizes the file cannot
// hold, and estimates what the library will allocate for the first part, so that the memory
// budget counts it before the library allocates anything.
#include <cstdint>
#include <string>
#include <vector>

namespace gloss {

struct ExrHeaderScan {
  // The first part's data window, pixels (OpenEXR's default header is 64 x 64).
  long long width = 64, height = 64;
  std::vector<std::string> channels;  // the first part's channel names, as stored
  int parts = 1;
  // An upper estimate of OpenEXR's own allocations for reading the first part: its chunk buffer
  // and the decompressor's buffers, the tile-row cache of a tiled part, the chunk tables.
  std::uint64_t library_bytes = 0;
};

// Walks path's magic number, version field and headers (every part of a multi-part file), and
// refuses, as an InputError naming path and the attribute: an unknown version or flags, a deep
// first part, a name or type name past the end of the file or longer than OpenEXR's 255
// characters, a declared value size that is negative or larger than the bytes left, a known
// type whose declared size is not the size OpenEXR reads (it would read past or short of it), a
// header that never ends, and chunk offset tables longer than the rest of the file.
ExrHeaderScan scan_exr_header(const std::string& path);

}  // namespace gloss

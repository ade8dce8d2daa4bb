// A PLY file's header, read and checked before a reader sees the file: readers allocate the
// element counts a header declares (1e9 vertices in a short file ends in std::bad_alloc), so
// every declared element must fit in the file's bytes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace opgraph {

struct PlyElement {
  std::string name;
  int64_t count = 0;
  int64_t min_bytes_each = 0;  // the least one element can take in this file's format
};

struct PlyHeader {
  std::string format;  // ascii, binary_little_endian or binary_big_endian
  std::vector<PlyElement> elements;
  bool HasFaces() const;
};

// Reads and checks the header of `path`; throws std::runtime_error with a one-line message
// naming the file and the problem (no end_header, an unknown format or property type, elements
// the file's bytes cannot hold).
PlyHeader CheckPlyFile(const std::string& path);

}  // namespace opgraph

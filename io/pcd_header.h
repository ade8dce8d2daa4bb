// A PCD file's header, read and checked before PCL sees the file: PCL's reader crashes on text
// that is not a PCD header and allocates whatever point count a header declares (1e9 points in
// a 250-byte file), so the header must be well formed and its data must fit in the file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace opgraph {

struct PcdHeader {
  std::vector<std::string> fields;
  std::vector<int> sizes, counts;
  std::vector<char> types;
  int64_t width = 0, height = 0, points = 0;
  std::string data;        // ascii, binary or binary_compressed
  int64_t data_offset = 0;  // bytes before the data
  int64_t PointSize() const;  // bytes per point
};

// The most points a PCD file may declare, and the most bytes its points may take unpacked.
constexpr int64_t kMaxPcdPoints = 100000000;
constexpr int64_t kMaxPcdBytes = int64_t{1} << 30;

// Reads and checks the header of `path`; throws std::runtime_error with a one-line message
// naming the file and the problem (an unknown line, a missing or inconsistent field, no x y z,
// a point count the file's bytes cannot hold or above the limits).
PcdHeader CheckPcdFile(const std::string& path);

}  // namespace opgraph

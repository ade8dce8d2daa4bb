#include "io/pcd_header.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "io/header_text.h"

namespace opgraph {
namespace {

constexpr int64_t kMaxHeaderBytes = 1 << 16;
constexpr size_t kMaxFields = 4096;

[[noreturn]] void Fail(const std::string& path, const std::string& message) {
  throw std::runtime_error(path + ": not a valid PCD file: " + message);
}

// The whole-string integer `token` in [lower, upper], else a failure naming `key`.
int64_t Integer(const std::string& path, const std::string& key, const std::string& token, int64_t lower, int64_t upper) {
  const bool digits = !token.empty() && token.size() <= 18 &&
                      std::all_of(token.begin(), token.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
  const int64_t value = digits ? std::stoll(token) : -1;
  if (!digits || value < lower || value > upper) {
    Fail(path, key + " " + Shown(token) + " is not an integer in [" + std::to_string(lower) + ", " + std::to_string(upper) + "]");
  }
  return value;
}

// The header's lines up to and including DATA (in `in`, the file's first 64 KB), as keys and
// values; `data_offset` is set past them.
void ParseLines(const std::string& path, std::istream& in, PcdHeader* header) {
  std::string line;
  bool has[6] = {};  // FIELDS, SIZE, TYPE, WIDTH, HEIGHT, DATA
  int line_number = 0;
  while (header->data.empty()) {
    if (!std::getline(in, line)) Fail(path, "no DATA line in the header (or in its first 64 KB)");
    ++line_number;
    header->data_offset += static_cast<int64_t>(line.size()) + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    std::string key, word;
    words >> key;
    std::vector<std::string> values;
    while (words >> word && values.size() <= kMaxFields) values.push_back(word);
    if (values.size() > kMaxFields) Fail(path, key + " lists more than 4096 values");
    const std::string where = "line " + std::to_string(line_number) + ": ";
    if (key == "VERSION" || key == "VIEWPOINT") continue;
    static const char* const kKeywords[] = {"FIELDS", "SIZE", "TYPE", "COUNT", "WIDTH", "HEIGHT", "POINTS", "DATA"};
    if (std::find(std::begin(kKeywords), std::end(kKeywords), key) == std::end(kKeywords)) {
      Fail(path, where + Shown(key) + " is not a PCD header keyword");
    }
    if (values.empty()) Fail(path, where + Shown(key) + " has no value");
    if (key == "FIELDS") {
      header->fields = values, has[0] = true;
    } else if (key == "SIZE") {
      for (const std::string& v : values) header->sizes.push_back(static_cast<int>(Integer(path, "SIZE", v, 1, 8)));
      has[1] = true;
    } else if (key == "TYPE") {
      for (const std::string& v : values) {
        if (v != "F" && v != "I" && v != "U") Fail(path, where + "TYPE " + Shown(v) + " is not F, I or U");
        header->types.push_back(v[0]);
      }
      has[2] = true;
    } else if (key == "COUNT") {
      for (const std::string& v : values) header->counts.push_back(static_cast<int>(Integer(path, "COUNT", v, 1, 1 << 20)));
    } else if (key == "WIDTH") {
      header->width = Integer(path, "WIDTH", values[0], 1, kMaxPcdPoints), has[3] = true;
    } else if (key == "HEIGHT") {
      header->height = Integer(path, "HEIGHT", values[0], 1, kMaxPcdPoints), has[4] = true;
    } else if (key == "POINTS") {
      header->points = Integer(path, "POINTS", values[0], 1, kMaxPcdPoints);
    } else if (key == "DATA") {
      if (values[0] != "ascii" && values[0] != "binary" && values[0] != "binary_compressed") {
        Fail(path, where + "DATA " + Shown(values[0]) + " is not ascii, binary or binary_compressed");
      }
      header->data = values[0], has[5] = true;
    }
  }
  const char* const names[] = {"FIELDS", "SIZE", "TYPE", "WIDTH", "HEIGHT", "DATA"};
  for (int k = 0; k < 6; ++k) {
    if (!has[k]) Fail(path, std::string("no ") + names[k] + " line");
  }
}

// The fields, their sizes, types and counts agree, x y z are among them, and the points fit.
void CheckConsistency(const std::string& path, PcdHeader* header) {
  const size_t n = header->fields.size();
  if (header->counts.empty()) header->counts.assign(n, 1);
  if (header->sizes.size() != n || header->types.size() != n || header->counts.size() != n) {
    Fail(path, "FIELDS, SIZE, TYPE and COUNT list different numbers of values");
  }
  for (const char* axis : {"x", "y", "z"}) {
    if (std::find(header->fields.begin(), header->fields.end(), axis) == header->fields.end()) {
      Fail(path, std::string("no field '") + axis + "'");
    }
  }
  if (header->width > kMaxPcdPoints / header->height) Fail(path, "WIDTH x HEIGHT is above 100000000 points");
  if (header->points == 0) header->points = header->width * header->height;
  if (header->points != header->width * header->height) Fail(path, "POINTS is not WIDTH x HEIGHT");
  if (header->PointSize() > kMaxPcdBytes / header->points) Fail(path, "the points would take more than 1 GB");
}

// The data after the header can hold the declared points.
void CheckDataSize(const std::string& path, std::istream& in, int64_t file_size, const PcdHeader& header) {
  const int64_t available = file_size - header.data_offset;
  const int64_t needed = header.points * header.PointSize();
  if (header.data == "binary" && available < needed) {
    Fail(path, "POINTS " + std::to_string(header.points) + " need " + std::to_string(needed) + " bytes of data; the file has " +
                   std::to_string(available));
  }
  if (header.data == "ascii") {
    // Each value takes at least one character and a separator.
    int64_t values_per_point = 0;
    for (int count : header.counts) values_per_point += count;
    if (available / 2 < header.points * values_per_point) {
      Fail(path, "POINTS " + std::to_string(header.points) + " do not fit in the file's " + std::to_string(available) +
                     " bytes of text");
    }
  }
  if (header.data == "binary_compressed") {
    uint32_t sizes[2] = {0, 0};  // compressed, uncompressed
    in.read(reinterpret_cast<char*>(sizes), sizeof(sizes));
    if (!in) Fail(path, "the compressed data has no size header");
    if (static_cast<int64_t>(sizes[1]) != needed) Fail(path, "the uncompressed size does not match POINTS");
    if (static_cast<int64_t>(sizes[0]) + 8 > available) Fail(path, "the compressed data is cut short");
  }
}

}  // namespace

int64_t PcdHeader::PointSize() const {
  int64_t size = 0;
  for (size_t f = 0; f < sizes.size() && f < counts.size(); ++f) size += int64_t{sizes[f]} * counts[f];
  return size;
}

PcdHeader CheckPcdFile(const std::string& path) {
  int64_t file_size = 0;
  std::istringstream lines(ReadFilePrefix(path, kMaxHeaderBytes, &file_size));
  PcdHeader header;
  ParseLines(path, lines, &header);
  CheckConsistency(path, &header);
  std::ifstream in(path, std::ios::binary);
  in.seekg(header.data_offset);
  CheckDataSize(path, in, file_size, header);
  return header;
}

}  // namespace opgraph

#include "io/ply_header.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "io/header_text.h"

namespace opgraph {
namespace {

constexpr int64_t kMaxHeaderBytes = 1 << 16;

[[noreturn]] void Fail(const std::string& path, const std::string& message) {
  throw std::runtime_error(path + ": not a valid PLY file: " + message);
}

// Bytes of a binary PLY scalar type, or 0 for an unknown one.
int ScalarBytes(const std::string& type) {
  static const std::map<std::string, int> kBytes = {
      {"char", 1},  {"uchar", 1},  {"int8", 1},   {"uint8", 1},   {"short", 2},   {"ushort", 2},  {"int16", 2},
      {"uint16", 2}, {"int", 4},   {"uint", 4},   {"int32", 4},   {"uint32", 4},  {"float", 4},   {"float32", 4},
      {"double", 8}, {"float64", 8}};
  const auto found = kBytes.find(type);
  return found == kBytes.end() ? 0 : found->second;
}

}  // namespace

bool PlyHeader::HasFaces() const {
  return std::any_of(elements.begin(), elements.end(), [](const PlyElement& e) { return e.name == "face" && e.count > 0; });
}

PlyHeader CheckPlyFile(const std::string& path) {
  int64_t file_size = 0;
  std::istringstream lines(ReadFilePrefix(path, kMaxHeaderBytes, &file_size));
  PlyHeader header;
  std::string line;
  int64_t header_bytes = 0;
  bool ended = false;
  for (int number = 1; !ended && std::getline(lines, line); ++number) {
    header_bytes += static_cast<int64_t>(line.size()) + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string key;
    words >> key;
    const std::string where = "line " + std::to_string(number) + ": ";
    if (number == 1) {
      if (key != "ply") Fail(path, "it does not start with 'ply'");
    } else if (key == "format") {
      words >> header.format;
      if (header.format != "ascii" && header.format != "binary_little_endian" && header.format != "binary_big_endian") {
        Fail(path, where + "format " + Shown(header.format) + " is unknown");
      }
    } else if (key == "element") {
      PlyElement element;
      std::string count;
      words >> element.name >> count;
      if (count.empty() || count.size() > 18 || !std::all_of(count.begin(), count.end(), ::isdigit)) {
        Fail(path, where + "element count " + Shown(count) + " is not an integer");
      }
      element.count = std::stoll(count);
      header.elements.push_back(element);
    } else if (key == "property") {
      if (header.elements.empty()) Fail(path, where + "a property before any element");
      std::string type, count_type, item_type;
      words >> type;
      const bool list = type == "list";
      if (list) words >> count_type >> item_type;
      const int bytes = ScalarBytes(list ? count_type : type);
      if (bytes == 0 || (list && ScalarBytes(item_type) == 0)) Fail(path, where + "unknown property type");
      // ascii: a value and a separator at the least; binary: the scalar, or a list's count.
      header.elements.back().min_bytes_each += header.format == "ascii" ? 2 : bytes;
    } else if (key == "end_header") {
      ended = true;
    } else if (key != "comment" && key != "obj_info" && !key.empty()) {
      Fail(path, where + Shown(key) + " is not a PLY header keyword");
    }
  }
  if (!ended) Fail(path, "no end_header in the first 64 KB");
  if (header.format.empty()) Fail(path, "no format line");
  // Every element must fit in the bytes after the header.
  const int64_t available = file_size - header_bytes;
  int64_t needed = 0;
  for (const PlyElement& element : header.elements) {
    const int64_t each = std::max<int64_t>(element.min_bytes_each, 1);
    if (element.count > (available - needed) / each) {
      Fail(path, "element " + Shown(element.name) + " declares " + std::to_string(element.count) + " but the file's " +
                     std::to_string(available) + " bytes of data cannot hold them");
    }
    needed += element.count * each;
  }
  return header;
}

}  // namespace opgraph

// Helpers for checking a file's text header before a third-party reader sees the file.
#pragma once

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "core/printable.h"

namespace opgraph {

// The first `max_bytes` of `path` (fewer when the file is shorter), read in one bounded piece:
// a file of binary noise may have no line break for getline to stop at. `file_size` is set.
inline std::string ReadFilePrefix(const std::string& path, int64_t max_bytes, int64_t* file_size) {
  std::error_code error;
  *file_size = static_cast<int64_t>(std::filesystem::file_size(path, error));
  std::ifstream in(path, std::ios::binary);
  if (!in || error) throw std::runtime_error(path + ": cannot open file");
  std::string prefix(static_cast<size_t>(std::min(*file_size, max_bytes)), '\0');
  in.read(prefix.data(), static_cast<std::streamsize>(prefix.size()));
  return prefix;
}

// `text` quoted for a one-line message, cut to 24 characters, unprintable bytes as '?'.
inline std::string Shown(const std::string& text) { return "'" + Printable(text, 24) + "'"; }

}  // namespace opgraph

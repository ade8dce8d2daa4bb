#include "tests/fuzz/fuzz_input_file.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace opgraph {

std::string WriteFuzzInput(const uint8_t* data, size_t size, const std::string& extension) {
  const char* tmpdir = std::getenv("TMPDIR");
  const std::string path = std::string(tmpdir != nullptr && *tmpdir != '\0' ? tmpdir : "/tmp") +
                           "/opgraph_fuzz_" + std::to_string(getpid()) + extension;
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr || (size > 0 && std::fwrite(data, 1, size, file) != size) || std::fclose(file) != 0) {
    std::perror(path.c_str());
    std::abort();  // the harness's own failure: stop rather than fuzz nothing
  }
  return path;
}

bool IsBadInputError(const std::exception& error) {
  return dynamic_cast<const std::runtime_error*>(&error) != nullptr ||
         dynamic_cast<const std::invalid_argument*>(&error) != nullptr ||
         dynamic_cast<const nlohmann::json::exception*>(&error) != nullptr ||
         dynamic_cast<const std::filesystem::filesystem_error*>(&error) != nullptr;
}

void AbortUnlessBadInput(const std::exception& error, const char* what) {
  if (IsBadInputError(error)) return;
  std::fprintf(stderr, "%s threw an error the tools would call their own: %s\n", what, error.what());
  std::abort();
}

void AbortIfInvalid(const Mesh& mesh, const char* what) {
  const std::string problem = mesh.Validate();
  if (problem.empty()) return;
  std::fprintf(stderr, "%s: %s\n", what, problem.c_str());
  std::abort();
}

}  // namespace opgraph

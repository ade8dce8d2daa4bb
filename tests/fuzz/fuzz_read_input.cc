// libFuzzer harness of ReadInput on one format, chosen at build time by OPGRAPH_FUZZ_EXTENSION
// (".obj", ".ply", ...; tests/fuzz/CMakeLists.txt builds one harness per format). A finding is
// a crash, a leak, a sanitizer report, a timeout, more than -rss_limit_mb of memory, or an
// exception the tools would call their own failure (exit 1) rather than the input's (exit 2).
#include <cstdint>
#include <exception>
#include <string>

#include "io/read_input.h"
#include "tests/fuzz/fuzz_input_file.h"

#ifndef OPGRAPH_FUZZ_EXTENSION
#error "OPGRAPH_FUZZ_EXTENSION must name the format's extension, e.g. \".obj\""
#endif

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string extension = OPGRAPH_FUZZ_EXTENSION;
  // glTF comes as JSON text (.gltf) or binary (.glb, magic "glTF"): one harness covers both.
  if (extension == ".gltf" && size >= 4 && std::string(reinterpret_cast<const char*>(data), 4) == "glTF") {
    extension = ".glb";
  }
  const std::string path = opgraph::WriteFuzzInput(data, size, extension);
  try {
    opgraph::AbortIfInvalid(opgraph::ReadInput(path).mesh, "ReadInput returned an invalid mesh");
  } catch (const std::exception& error) {
    opgraph::AbortUnlessBadInput(error, "ReadInput");
  }
  return 0;
}

// The fuzz harnesses' shared parts: a fuzzer's bytes as a file the library reads by path, and the
// line between an input the tools refuse (exit 2) and a bug (apps/tool_errors.cc).
#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

#include "core/mesh.h"

namespace opgraph {

// Writes `size` bytes to a file of this process named "<TMPDIR>/opgraph_fuzz_<pid><extension>",
// overwritten on every call, and returns its path.
std::string WriteFuzzInput(const uint8_t* data, size_t size, const std::string& extension);

// True for the exceptions the library throws about bad input (std::runtime_error,
// std::invalid_argument, a JSON or filesystem error): the tools report them with exit code 2.
// Anything else (std::bad_alloc, a logic_error, a CGAL failure) is a finding.
bool IsBadInputError(const std::exception& error);

// Findings: abort, naming `what`, when `error` is not a bad-input error, or when `mesh` (a result
// the library accepted) has a non-finite vertex or a face outside its vertices.
void AbortUnlessBadInput(const std::exception& error, const char* what);
void AbortIfInvalid(const Mesh& mesh, const char* what);

}  // namespace opgraph

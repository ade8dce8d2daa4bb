// Runs a third-party reader in a child process, so that a malformed file that crashes, aborts or
// leaks inside it (Assimp 5.2 does on some PLY, OFF, STL and glTF files; tests/fuzz found them)
// takes down only the child.
#pragma once

#include <functional>
#include <string>

#include "io/read_input.h"

namespace opgraph {

// Forks, runs `read` in the child and returns what it read (copied back through a pipe). An
// exception `read` throws comes back as std::runtime_error with its message; a child that dies
// (a signal, an abort) gives std::runtime_error "PATH: cannot read it: the reader crashed on it
// (SIGNAL NAME)". The child touches nothing of the parent's: state it sets up before the call
// (a logger, a verbosity level) must be set up by the caller, in the parent, beforehand.
// A child still reading after `time_limit_seconds` (<= 0: ReaderTimeLimitSeconds(path)) is
// killed, and std::runtime_error "PATH: cannot read it: the reader did not finish within N s ..."
// is thrown (Assimp 5.2 loops forever on some malformed files).
InputGeometry ReadInChildProcess(const std::string& path, const std::function<InputGeometry()>& read,
                                 double time_limit_seconds = 0);

// The default time limit of reading `path`: 10 s plus 5 s per MiB of the file, some thirty times
// what Assimp takes on a well-formed file (6.3 s for a 36 MiB binary PLY of 2 M triangles).
double ReaderTimeLimitSeconds(const std::string& path);

}  // namespace opgraph

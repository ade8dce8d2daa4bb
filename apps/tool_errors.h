// The tools' edge: every exception a library call lets out becomes one line on stderr naming the
// file it concerns, and an exit code: 2 for bad input (the library's errors about a file or a
// sequence: std::runtime_error and std::invalid_argument, a JSON or filesystem error), 1 for a
// failure of the tool itself (out of memory, a broken invariant: any other exception).
#pragma once

#include <exception>
#include <string>

namespace opgraph {

// Prints "tool: file: message" (the file left out when the message starts with it already, as
// the readers' messages do) with raw library text tidied ("[json.exception.parse_error.101]",
// "std::bad_alloc") and control characters escaped; returns the exit code.
int ReportException(const std::string& tool, const std::string& file, const std::exception& error);

// Like ReportException, for the tool's own work after the input was read (rendering, writing
// the outputs): every failure is the tool's (exit 1).
int ReportInternalFailure(const std::string& tool, const std::string& what, const std::exception& error);

// A tool's main: `run` with anything it lets out (out of memory while computing a report) still
// reported as one line, exit code 1.
int RunAtToolEdge(const std::string& tool, int (*run)(int, char**), int argc, char** argv);

}  // namespace opgraph

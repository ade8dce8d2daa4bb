// The command lines of the opgraph tools: gflags' flags (DEFINE_int64(work_budget, ...) in the
// tool's file), read by one parser that keeps the tools' contract for bad input: one line on
// stderr naming the argument, exit code 2, nothing done. gflags' own parser prints several
// "ERROR:" lines and exits 1 (and kills the program on an unreadable --flagfile), so this one
// reads argv itself and sets each flag through gflags::SetCommandLineOption.
//
// Every tool accepts: --name=value and --name value; dashes or underscores in names
// (--work-budget is --work_budget); --no-name, --noname and --name=false for a bool;
// --flagfile FILE (one --name=value a line, # comments); -- (everything after it is an
// argument); --help / -h (the usage line and the tool's own flags with their defaults and
// meanings, exit 0) and --version (exit 0).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "ops/limits.h"

namespace opgraph {

struct CommandLineOptions {
  std::string tool;   // the name errors start with: "fit_sequence"
  std::string usage;  // the synopsis --help starts with
  // __FILE__ of the file holding the tool's DEFINE_ lines: --help lists the flags defined there
  // (not those of gflags itself or of linked libraries such as glog). Empty: no flags.
  std::string flags_file;
  int max_arguments = 0;  // how many arguments that are not flags the tool takes at most
};

struct ParsedCommandLine {
  std::vector<std::string> arguments;  // those that are not flags, in order
  bool help = false;
  bool version = false;
  std::string error;  // the first problem, naming the argument as typed; empty when fine
};

// Sets the flags `args` name (argv without the program name). Stops at the first problem.
// --help and --version win over any problem, wherever they stand.
ParsedCommandLine ParseCommandLine(const std::vector<std::string>& args, int max_arguments);

// ParseCommandLine on main's argv; prints the help or the version and exits 0, or prints
// "tool: error" and exits 2. Returns the arguments that are not flags.
std::vector<std::string> ParseCommandLineOrExit(int argc, char** argv, const CommandLineOptions& options);

// The --help text: the usage line, then each of the tool's flags with its type, default and
// meaning, then the flags every tool takes.
std::string CommandLineHelp(const CommandLineOptions& options);

// opgraph's version (CMake's project(VERSION)), as --version prints it.
const char* OpgraphVersion();

// The longest error line the tools print (a line on a terminal, not a dump).
constexpr size_t kMaxErrorChars = 600;

// Prints "tool: message" on stderr as one line (control characters shown as '?', a long
// message cut); returns 2, the exit code for bad input.
int BadInput(const std::string& tool, const std::string& message);

// --max-faces, shared by fit_sequence and apply_sequence: its meaning for --help, and its check
// (empty when fine, else the problem in the command line's words).
const char* MaxFacesHelp();
std::string CheckMaxFaces(int64_t max_faces);

}  // namespace opgraph

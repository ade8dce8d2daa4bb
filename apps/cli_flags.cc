#include "apps/cli_flags.h"

#include <gflags/gflags.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include "core/printable.h"

namespace opgraph {
namespace {

// A flagfile may name another; deeper than this is a loop.
constexpr int kMaxFlagfileDepth = 8;

// An argument as quoted in an error: a long one is cut (a line on a terminal, not a dump).
std::string Shown(const std::string& text) { return text.size() > 80 ? text.substr(0, 80) + "..." : text; }

// "--work-budget=9" -> "work_budget"; empty for an argument that is not a flag.
std::string FlagName(const std::string& arg) {
  if (arg.size() < 2 || arg[0] != '-') return "";
  const size_t start = arg[1] == '-' ? 2 : 1;
  std::string name = arg.substr(start, arg.find('=') - start);
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

bool IsHelp(const std::string& name) {
  return name == "h" || name == "help" || name == "helpshort" || name == "helpfull";
}

// What a value of gflags' type `type` looks like, for "--seed: expected ..., not 'x'".
std::string ExpectedValue(const std::string& type) {
  if (type == "bool") return "true or false";
  if (type == "uint32" || type == "uint64") return "an integer >= 0";
  if (type == "int32" || type == "int64") return "an integer";
  if (type == "double") return "a number";
  return "a " + type;
}

class ArgumentReader {
 public:
  ArgumentReader(int max_arguments, ParsedCommandLine* parsed) : max_arguments_(max_arguments), parsed_(parsed) {}

  // Reads `args`: the command line (`source` empty) or a flagfile's flag lines, whose values
  // follow '=' (as in gflags' flagfiles). False at the first problem, left in parsed_->error.
  bool Read(const std::vector<std::string>& args, const std::string& source, int depth) {
    for (size_t i = 0; i < args.size(); ++i) {
      const std::string& arg = args[i];
      if (arg == "--" && source.empty()) {
        for (++i; i < args.size(); ++i) {
          if (!AddArgument(args[i])) return false;
        }
        return true;
      }
      if (arg.size() < 2 || arg[0] != '-') {  // "-" alone is an argument too (stdin, by custom)
        if (!AddArgument(arg)) return false;
        continue;
      }
      const std::string name = FlagName(arg);
      const size_t equals = arg.find('=');
      const std::string typed = arg.substr(0, equals);  // as written: "--work-budget"
      std::optional<std::string> value;
      if (equals != std::string::npos) value = arg.substr(equals + 1);
      if (IsHelp(name) || name == "version") {  // from a flagfile; the command line's are seen first
        (IsHelp(name) ? parsed_->help : parsed_->version) = true;
        continue;
      }
      gflags::CommandLineFlagInfo flag;
      if (!gflags::GetCommandLineFlagInfo(name.c_str(), &flag)) {
        // --no-name and --noname: a bool turned off.
        const std::string negated = name.rfind("no", 0) == 0 ? name.substr(name[2] == '_' ? 3 : 2) : "";
        if (negated.empty() || value || !gflags::GetCommandLineFlagInfo(negated.c_str(), &flag) || flag.type != "bool") {
          return Fail(source, "unknown flag '" + Shown(typed) + "'");
        }
        value = "false";
      } else if (!value && flag.type == "bool") {
        value = "true";
      } else if (!value) {
        if (!source.empty() || i + 1 == args.size()) return Fail(source, "flag '" + Shown(typed) + "' is missing its value");
        value = args[++i];
      }
      if (flag.name == "flagfile") {
        // Not through gflags: it ends the program on a file it cannot read, and ignores lines
        // it does not understand.
        if (!ReadFlagfile(*value, depth + 1)) return false;
      } else if (gflags::SetCommandLineOption(flag.name.c_str(), value->c_str()).empty()) {
        return Fail(source, Shown(typed) + ": expected " + ExpectedValue(flag.type) + ", not '" + Shown(*value) + "'");
      }
    }
    return true;
  }

 private:
  bool Fail(const std::string& source, const std::string& message) {
    parsed_->error = (source.empty() ? "" : "--flagfile " + Shown(source) + ": ") + message;
    return false;
  }

  bool AddArgument(const std::string& arg) {
    if (static_cast<int>(parsed_->arguments.size()) >= max_arguments_) {
      return Fail("", "unexpected argument '" + Shown(arg) + "'");
    }
    parsed_->arguments.push_back(arg);
    return true;
  }

  // gflags' flagfile format: a flag a line, blank lines and lines starting with # skipped.
  bool ReadFlagfile(const std::string& path, int depth) {
    if (depth > kMaxFlagfileDepth) return Fail(path, "flagfiles nested deeper than " + std::to_string(kMaxFlagfileDepth));
    std::ifstream in(path);
    if (!in) return Fail("", "--flagfile: cannot open '" + Shown(path) + "'");
    std::vector<std::string> flags;
    for (std::string line; std::getline(in, line);) {
      const size_t first = line.find_first_not_of(" \t\r"), last = line.find_last_not_of(" \t\r");
      if (first == std::string::npos || line[first] == '#') continue;
      line = line.substr(first, last + 1 - first);
      if (line.size() < 2 || line[0] != '-') return Fail(path, "expected a --name=value line, not '" + Shown(line) + "'");
      flags.push_back(line);
    }
    return Read(flags, path, depth);
  }

  const int max_arguments_;
  ParsedCommandLine* const parsed_;
};

// `text` word-wrapped to lines of at most `width` characters after `indent`.
std::string Wrapped(const std::string& text, const std::string& indent, size_t width) {
  std::istringstream words(text);
  std::string out, line;
  for (std::string word; words >> word;) {
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += indent + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) out += indent + line + "\n";
  return out;
}

// A flag's name as the tools' documentation writes it: --work-budget.
std::string DocumentedName(const gflags::CommandLineFlagInfo& flag) {
  std::string name = flag.name;
  std::replace(name.begin(), name.end(), '_', '-');
  return "--" + name;
}

}  // namespace

ParsedCommandLine ParseCommandLine(const std::vector<std::string>& args, int max_arguments) {
  ParsedCommandLine parsed;
  // --help and --version before anything is set or refused: no work, whatever else is given.
  for (const std::string& arg : args) {
    if (arg == "--") break;
    parsed.help |= IsHelp(FlagName(arg));
    parsed.version |= FlagName(arg) == "version";
  }
  if (parsed.help || parsed.version) return parsed;
  ArgumentReader(max_arguments, &parsed).Read(args, "", 0);
  return parsed;
}

std::vector<std::string> ParseCommandLineOrExit(int argc, char** argv, const CommandLineOptions& options) {
  const ParsedCommandLine parsed = ParseCommandLine(std::vector<std::string>(argv + 1, argv + argc), options.max_arguments);
  if (parsed.help) {
    std::cout << CommandLineHelp(options);
    std::exit(0);
  }
  if (parsed.version) {
    std::cout << options.tool << " (opgraph) " << OpgraphVersion() << "\n";
    std::exit(0);
  }
  if (!parsed.error.empty()) std::exit(BadInput(options.tool, parsed.error + " (see --help)"));
  return parsed.arguments;
}

std::string CommandLineHelp(const CommandLineOptions& options) {
  std::string help = options.usage + "\n\nflags (--name=value or --name value; - or _ in names; --no-name turns a bool off):\n";
  std::vector<gflags::CommandLineFlagInfo> flags;
  gflags::GetAllFlags(&flags);  // sorted by name within a file
  for (const gflags::CommandLineFlagInfo& flag : flags) {
    if (options.flags_file.empty() || flag.filename != options.flags_file) continue;
    const std::string default_value = flag.type == "string" ? "\"" + flag.default_value + "\"" : flag.default_value;
    help += "  " + DocumentedName(flag) + " (" + flag.type + ", default " + default_value + ")\n";
    help += Wrapped(flag.description, "      ", 90);
  }
  help += "  --flagfile FILE\n      reads flags from FILE: one --name=value a line, # starts a comment\n";
  help += "  --help, -h\n      prints this and exits\n";
  help += "  --version\n      prints the version (" + std::string(OpgraphVersion()) + ") and exits\n";
  return help;
}

const char* OpgraphVersion() { return OPGRAPH_VERSION; }

int BadInput(const std::string& tool, const std::string& message) {
  std::cerr << tool << ": " << Printable(message, kMaxErrorChars) << "\n";
  return 2;
}

const char* MaxFacesHelp() {
  static const std::string help = "the most faces any step of the sequence may have, in [1, " +
                                  std::to_string(kMaxFacesCeiling) +
                                  "]; all steps together may have 4 times as many; a sequence that grows beyond it "
                                  "is refused, naming the op";
  return help.c_str();
}

std::string CheckMaxFaces(int64_t max_faces) {
  if (max_faces < 1 || max_faces > kMaxFacesCeiling) {
    return "--max-faces: expected an integer in [1, " + std::to_string(kMaxFacesCeiling) + "]";
  }
  return "";
}

}  // namespace opgraph

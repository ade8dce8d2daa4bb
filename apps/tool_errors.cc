#include "apps/tool_errors.h"

#include <filesystem>
#include <iostream>
#include <new>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "core/printable.h"

namespace opgraph {
namespace {

// The longest message printed; a longer one is cut (a line on a terminal, not a dump).
constexpr size_t kMaxMessageChars = 600;

// The exception's text in the tools' words, and whether it is about the input.
struct Translated {
  std::string message;
  bool bad_input = false;
};

Translated Translate(const std::exception& error) {
  if (dynamic_cast<const std::bad_alloc*>(&error) != nullptr) {
    return {"out of memory (the input asks for more than this machine has)", false};
  }
  if (const auto* json = dynamic_cast<const nlohmann::json::exception*>(&error)) {
    // "[json.exception.type_error.302] type must be number" -> "invalid JSON: type must be number"
    const std::string what = json->what();
    const size_t end = what.find("] ");
    return {"invalid JSON: " + (end == std::string::npos ? what : what.substr(end + 2)), true};
  }
  if (const auto* fs_error = dynamic_cast<const std::filesystem::filesystem_error*>(&error)) {
    const std::string path = fs_error->path1().string();
    return {fs_error->code().message() + (path.empty() ? "" : " (" + path + ")"), true};
  }
  // The library's own errors about the input (readers, sequences, targets) are runtime_error
  // and invalid_argument; anything else (logic_error, a CGAL precondition) is a bug.
  const bool bad_input = dynamic_cast<const std::runtime_error*>(&error) != nullptr ||
                         dynamic_cast<const std::invalid_argument*>(&error) != nullptr;
  return {bad_input ? error.what() : std::string("internal error: ") + error.what(), bad_input};
}

void PrintLine(const std::string& tool, const std::string& file, const std::string& message) {
  const bool names_file = !file.empty() && message.compare(0, file.size(), file) == 0;
  const std::string line = names_file || file.empty() ? message : file + ": " + message;
  std::cerr << tool << ": " << Printable(line, kMaxMessageChars) << "\n";
}

}  // namespace

int ReportException(const std::string& tool, const std::string& file, const std::exception& error) {
  const Translated translated = Translate(error);
  PrintLine(tool, file, translated.message);
  return translated.bad_input ? 2 : 1;
}

int ReportInternalFailure(const std::string& tool, const std::string& what, const std::exception& error) {
  PrintLine(tool, what, Translate(error).message);
  return 1;
}

int RunAtToolEdge(const std::string& tool, int (*run)(int, char**), int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    return ReportInternalFailure(tool, "", e);
  }
}

}  // namespace opgraph

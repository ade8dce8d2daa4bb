#include "tests/blender_runner.h"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/obj_io.h"

namespace opgraph {

std::string ShellQuote(const std::string& s) { return "'" + s + "'"; }

std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

Mesh RunBlender(const std::string& script, const std::string& out_obj) {
  const std::string log = out_obj + ".log";
  const std::string command = "blender -b --factory-startup --python-exit-code 1 -P " + ShellQuote(script) + " -- " +
                              ShellQuote(out_obj) + " > " + ShellQuote(log) + " 2>&1";
  if (std::system(command.c_str()) != 0) {
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    throw std::runtime_error("blender failed (" + command + "):\n" + text.str());
  }
  return ReadObj(out_obj);
}

std::vector<std::string> ExportedModifiers(const std::string& out_obj) {
  std::ifstream in(out_obj);
  std::vector<std::string> names;
  const std::string prefix = "# modifier ";
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(prefix, 0) != 0) continue;
    std::string name = line.substr(prefix.size());
    const size_t dot = name.rfind('.');
    if (dot != std::string::npos && dot + 1 < name.size() &&
        name.find_first_not_of("0123456789", dot + 1) == std::string::npos) {
      name.resize(dot);
    }
    names.push_back(name);
  }
  return names;
}

}  // namespace opgraph

// Runs a rebuild_blender.py in real Blender 3.4 (headless) and reads back the mesh it wrote.
#pragma once

#include <string>
#include <vector>

#include "core/mesh.h"

namespace opgraph {

// The whole text of a file (empty when it cannot be read).
std::string ReadText(const std::string& path);

// A single-quoted shell word (paths here never hold quotes).
std::string ShellQuote(const std::string& s);

// Runs `script` with `-- out_obj`, its output to out_obj + ".log". Throws std::runtime_error
// with the log when Blender fails.
Mesh RunBlender(const std::string& script, const std::string& out_obj);

// The modifiers the rebuilt object kept, from the "# modifier NAME" lines of the OBJ the script
// exported, with Blender's ".001" suffixes removed.
std::vector<std::string> ExportedModifiers(const std::string& out_obj);

}  // namespace opgraph

// Converts a ../shared/data/gt-dev sequence.json (Blender-recorded, its own format) into an
// opgraph sequence document.
#pragma once

#include <filesystem>
#include <string>

#include "ops/params.h"

namespace opgraph {

// Returns the converted document; sets *why_not (and returns null) when the sequence uses an
// op or option opgraph does not implement yet.
Json ConvertGtSequence(const std::filesystem::path& path, std::string* why_not);

}  // namespace opgraph

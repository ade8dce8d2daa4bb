// Text from a user's file made safe for a one-line message.
#pragma once

#include <cctype>
#include <string>

namespace opgraph {

// `text` cut to `max_chars` ("..." marks a cut) with anything unprintable (a line break, a
// terminal escape, a byte of binary noise) shown as '?'.
inline std::string Printable(const std::string& text, size_t max_chars = 40) {
  std::string shown = text.substr(0, max_chars);
  for (char& c : shown) c = std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  return text.size() > max_chars ? shown + "..." : shown;
}

}  // namespace opgraph

// The corpus protocol's fixed split rules (docs/corpus.md): which models tune the search and
// which are held out, only measured.
#pragma once

namespace opgraph {

// Synthetic model `index` is held out when its last digit is 7, 8 or 9 (60 of the default 200).
inline bool SynthHeldOut(int index) { return index % 10 >= 7; }

// real-train models, sorted by name: the odd positions (1, 3, 5, ...) are held out.
inline bool RealHeldOut(int sorted_position) { return sorted_position % 2 == 1; }

}  // namespace opgraph

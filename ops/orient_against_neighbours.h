// Consistent winding for faces added next to faces already wound: Bevel's new faces against the
// rebuilt originals.
#pragma once

#include <vector>

#include "core/mesh.h"

namespace opgraph {

// Reverses faces[num_oriented ..] as needed so that each runs the edge by which it is first
// reached the other way from the face reaching it: breadth first from faces 0 .. num_oriented - 1,
// whose winding is kept, faces by index and their edges by corner. A face no chain reaches keeps
// its winding. For Bevel's new faces against the rebuilt originals: only the faces to orient are
// indexed (their edges listed by lower vertex), far cheaper than a half-edge mesh of all faces.
void OrientAgainstNeighbours(int num_oriented, std::vector<Polygon>* faces);

}  // namespace opgraph

// The finishing steps after the search: gate pruning, a polishing fit, simplification and the
// modeller's op order.
#pragma once

#include "search/evaluator.h"
#include "search/layout.h"
#include "search/zero_shot.h"

namespace opgraph {

// Gates: ops that do not earn their place are pruned (kept only when the loss stays within the
// price of one op and the result replays), else the searched sequence is polished with more
// samples; then ops the Chamfer distance does not need are dropped and the scale is written
// first where that builds the same mesh.
ZeroShotResult Finish(Evaluator* evaluator, const Trial& best);

}  // namespace opgraph

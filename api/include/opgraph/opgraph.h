// The entry header as a consumer includes it: #include <opgraph/opgraph.h> (the API itself is
// api/opgraph.h; this name keeps a consumer's includes apart from its own core/, ops/, ...).
#pragma once

#include "api/opgraph.h"

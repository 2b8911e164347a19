// Fixture: the one offending include of this tree (core never draws).
#include <vector>

#include "util/bits.h"

#include <GL/gl.h>

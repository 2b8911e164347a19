#pragma once
// Fixture: the one offending include of this tree (util may not use mesh).

#include <cstdint>

#include "mesh/shape.h"
#include "util/span_rows_detail.h"

#pragma once
// Fixture: mesh may use util (declared), so this include is allowed.

#include "util/span_rows_detail.h"

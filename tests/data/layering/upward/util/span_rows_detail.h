#pragma once
// Fixture: an include of the folder itself, allowed.
#include <vector>

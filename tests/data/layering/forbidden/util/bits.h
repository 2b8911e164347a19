#pragma once
// Fixture: nothing wrong here.
#include <cstdint>

#pragma once
// Tools that scripts/install-deps.sh installs (ccx, tetgen, ...) are part of the test set-up: a
// test that needs one fails when it is missing instead of skipping, so a machine that lacks it
// cannot pass the suite by running fewer tests.

#include <gtest/gtest.h>

/// Fails the current test (and returns from it) when `available` is false.
#define SCULPT_REQUIRE_TOOL(available, tool)                                            \
  ASSERT_TRUE(available) << tool << " is not on PATH; scripts/install-deps.sh installs it " \
                                    "(the tests that need it fail rather than skip)"

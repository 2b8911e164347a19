# Fixture for the layering check (tests/layering/expect_failure.cmake): mesh sits on util.
set(SCULPT_LAYERING_FOLDERS util mesh)
set(SCULPT_LAYERING_DEPS_util)
set(SCULPT_LAYERING_DEPS_mesh util)

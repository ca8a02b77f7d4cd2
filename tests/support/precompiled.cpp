// Compiles nothing of its own: it gives the test programs' precompiled header (tests/CMakeLists.txt,
// cloudshape_test_pch) a target to be built in, with the test programs' compile flags.

// Compiles nothing of its own: it gives the libraries' precompiled header (common/CMakeLists.txt,
// cloudshape_common_pch) a target to be built in, with the libraries' compile flags.

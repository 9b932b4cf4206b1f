// The translation unit that owns the tests' precompiled Catch2 header (CMakeLists.txt,
// cmp_catch_pch); it defines nothing.

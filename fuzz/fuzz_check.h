// FUZZ_CHECK(condition, meaning): an invariant of a fuzz target. Unlike assert() it stays
// on in release builds. A failure prints the condition and what it means, then abort()s,
// which libFuzzer reports as a crash and saves the input that caused it.
#pragma once

#include <cstdio>
#include <cstdlib>

#define FUZZ_CHECK(condition, meaning)                                                   \
  do {                                                                                   \
    if (!(condition)) {                                                                  \
      std::fprintf(stderr, "fuzz invariant failed: %s (%s) at %s:%d\n", #condition,      \
                   meaning, __FILE__, __LINE__);                                         \
      std::abort();                                                                      \
    }                                                                                    \
  } while (false)

// The host tests' one assertion: counts the check, and on failure counts it and prints where. Each test
// program defines `int checks` and `int failures` (in an anonymous namespace) before including this.
#ifndef HAPTICON_TEST_CHECK_H
#define HAPTICON_TEST_CHECK_H

#include <stdio.h>

#define CHECK(condition)                                                            \
  do {                                                                              \
    checks++;                                                                       \
    if (!(condition)) {                                                             \
      failures++;                                                                   \
      fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #condition); \
    }                                                                               \
  } while (0)

#endif

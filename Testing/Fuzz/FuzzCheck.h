// The fuzz targets' invariant check: CHECK(condition, printf-style message)
// prints "<target>: INVARIANT FAILED: <message>" (what RunFuzz.cmake looks
// for) and aborts, so that libFuzzer keeps the input. Define FUZZ_TARGET_NAME
// before including.
#ifndef shapesplines_FuzzCheck_h
#define shapesplines_FuzzCheck_h

#include <cstdarg>
#include <cstdio>
#include <cstdlib>

[[noreturn]] inline void fuzzFail(const char* format, ...)
{
  std::fprintf(stderr, "\n%s: INVARIANT FAILED: ", FUZZ_TARGET_NAME);
  va_list args;
  va_start(args, format);
  std::vfprintf(stderr, format, args);
  va_end(args);
  std::fprintf(stderr, "\n");
  std::fflush(stderr);
  std::abort();
}

#define CHECK(condition, ...)                                                                      \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      fuzzFail(__VA_ARGS__);                                                                       \
    }                                                                                              \
  } while (false)

#endif

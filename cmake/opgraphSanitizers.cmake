# Instrumented builds for testing opgraph itself, never for users: `scripts/test.sh --sanitize`
# (OPGRAPH_SANITIZE: AddressSanitizer and UndefinedBehaviorSanitizer on every target, the whole
# suite run under them) and `scripts/fuzz.sh` (OPGRAPH_BUILD_FUZZERS: clang's libFuzzer
# harnesses of tests/fuzz, on libraries built with the same sanitizers).
option(OPGRAPH_SANITIZE "Build every target with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(OPGRAPH_BUILD_FUZZERS "Build the libFuzzer harnesses of tests/fuzz (clang; sanitizes everything)" OFF)

set(OPGRAPH_SANITIZER_FLAGS -fsanitize=address,undefined -fno-omit-frame-pointer)
if(OPGRAPH_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "OPGRAPH_BUILD_FUZZERS needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  list(APPEND OPGRAPH_SANITIZER_FLAGS -fsanitize=fuzzer-no-link)
endif()
if(OPGRAPH_SANITIZE OR OPGRAPH_BUILD_FUZZERS)
  add_compile_options(${OPGRAPH_SANITIZER_FLAGS})
  add_link_options(-fsanitize=address,undefined)
endif()

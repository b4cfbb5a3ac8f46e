# Project-wide build settings, linked PRIVATE into every target we build (earcut's `common`,
# fmt's PEDANTIC_COMPILE_FLAGS). Consumers of the installed library inherit none of them.

# One deliberate fault (src/fault_injection.h), for scripts/fault-table.sh; empty in real builds.
# Only the code that holds the faults is compiled with it (the library, the oracles, and the two
# tests that include src/ headers), so that a fault build recompiles those alone and the rest
# comes from ccache.
set(TILESWEEP_FAULT "" CACHE STRING "Build the library with one deliberate fault (see src/fault_injection.h)")
set(tilesweep_fault_definitions "")
if(TILESWEEP_FAULT)
    message(WARNING "tilesweep is built with the deliberate fault ${TILESWEEP_FAULT}")
    set(tilesweep_fault_definitions TILESWEEP_FAULT_${TILESWEEP_FAULT})
endif()

# Fused multiply-add changes the rounding of a*b+c; the library's exact arithmetic (Dekker's
# TwoProduct, Knuth's TwoSum), the oracles, the corpus replay and the bit-for-bit comparisons
# assume every product and sum is rounded on its own (box2d, earcut). GCC's default is
# -ffp-contract=fast, so this is set on the library targets themselves (src/CMakeLists.txt), not
# only here: a game that builds them with its own flags keeps it. MSVC does not contract unless
# asked (/fp:contract). The library checks the arithmetic it gets at run time too
# (src/arithmetic_check.cpp).
set(tilesweep_fp_contract
    $<$<NOT:$<CXX_COMPILER_ID:MSVC>>:$<IF:$<STREQUAL:${TILESWEEP_FAULT},FMA>,-ffp-contract=fast,-ffp-contract=off>>)
# The deliberate fault FMA means something only where the processor has the instruction: on
# x86-64 it also builds for x86-64-v3 (FMA3, AVX2), so that the compiler can fuse. On the
# x86-64 baseline -ffp-contract=fast alone changes nothing.
if(TILESWEEP_FAULT STREQUAL "FMA" AND CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64")
    list(APPEND tilesweep_fp_contract -march=x86-64-v3)
endif()

# Every function starts on a 64-byte boundary (a cache line), so that the layout of a hot loop
# inside it, and with it the speed of the loop, stays the same when code elsewhere in the binary
# grows or shrinks: left to the linker's packing, unchanged code runs at another speed after an
# edit to another file (scripts/compare-commits.sh shows it). On every target: the library and the
# baselines it is measured against (bench/) alike.
set(tilesweep_code_alignment $<$<NOT:$<CXX_COMPILER_ID:MSVC>>:-falign-functions=64>)

add_library(tilesweep_warnings INTERFACE)
target_compile_options(tilesweep_warnings INTERFACE
    -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion
    ${tilesweep_fp_contract} ${tilesweep_code_alignment}
    # GoogleTest's TYPED_TEST_SUITE(Suite, Types) leaves its variadic argument empty, which clang's
    # -Wpedantic reports at every use.
    $<$<CXX_COMPILER_ID:Clang>:-Wno-gnu-zero-variadic-macro-arguments>
    $<$<BOOL:${TILESWEEP_WERROR}>:-Werror>)

# Boost's headers are not written for that set: every Boost include sits between
# tilesweep/boost_warnings_off.h and boost_warnings_on.h (cmake/include/), which turn the warnings
# they trip off and on again. The oracles link this PUBLIC (their rational.h includes Boost), the
# exact safety checks PRIVATE.
add_library(tilesweep_boost_warnings INTERFACE)
target_include_directories(tilesweep_boost_warnings INTERFACE ${CMAKE_CURRENT_LIST_DIR}/include)


if(TILESWEEP_SANITIZE AND TILESWEEP_SANITIZE_THREAD)
    message(FATAL_ERROR "tilesweep: TILESWEEP_SANITIZE and TILESWEEP_SANITIZE_THREAD cannot be combined")
endif()
if(TILESWEEP_SANITIZE_THREAD)
    # ThreadSanitizer over the batch pool (preset tsan); like the others, on every target.
    add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
    add_link_options(-fsanitize=thread)
endif()
if(TILESWEEP_SANITIZE)
    # Sanitizers must cover everything, so they go on every target, including third-party code
    # compiled here (box2d).
    add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
    add_link_options(-fsanitize=address,undefined)
    # A C program linked by clang against the C++ library (tests/c_api/) needs the sanitizers' C++
    # runtime and libstdc++, which the C driver leaves out.
    if(CMAKE_C_COMPILER_ID MATCHES "Clang")
        add_link_options($<$<LINK_LANGUAGE:C>:-fsanitize-link-c++-runtime> $<$<LINK_LANGUAGE:C>:-lstdc++>)
    endif()
endif()

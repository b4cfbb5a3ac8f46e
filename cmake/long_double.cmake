# TILESWEEP_HAVE_WIDE_LONG_DOUBLE: whether long double holds every float and double and their
# sums exactly (x87 extended, or binary128 as on Linux arm64), as checks/exact_sum.h needs. It is
# not on MSVC (long double is double) or on Apple arm64.
include(CheckCXXSourceCompiles)
check_cxx_source_compiles([=[
#include <limits>
static_assert(std::numeric_limits<long double>::radix == 2 &&
              std::numeric_limits<long double>::digits >= 64 &&
              std::numeric_limits<long double>::max_exponent >= 16384, "narrow long double");
int main() { return 0; }
]=] TILESWEEP_HAVE_WIDE_LONG_DOUBLE)

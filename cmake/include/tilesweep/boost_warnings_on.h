// SPDX-License-Identifier: MIT
// Restores the warnings boost_warnings_off.h turned off. No include guard: it pops once per use.
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

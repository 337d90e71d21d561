#pragma once
// RTVK_ASAN: 1 in a build under AddressSanitizer. GCC says so with __SANITIZE_ADDRESS__; clang
// before 16 only through __has_feature(address_sanitizer) (the asan preset builds with clang 14).
#if defined(__SANITIZE_ADDRESS__)
#define RTVK_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RTVK_ASAN 1
#endif
#endif
#if !defined(RTVK_ASAN)
#define RTVK_ASAN 0
#endif

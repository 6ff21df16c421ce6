// Whether this test binary runs under AddressSanitizer (scripts/build-san.sh), where
// double-precision numerics run ~15x slower: the few checks that need minutes there skip
// under it and run in the optimised build (scripts/test.sh runs both).
#pragma once

namespace cloudsvc::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitizerBuild = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitizerBuild = true;
#else
inline constexpr bool kSanitizerBuild = false;
#endif
#else
inline constexpr bool kSanitizerBuild = false;
#endif

// What a test that skips in the sanitizer build says.
inline constexpr const char* kSlowUnderSanitizers = "minutes under AddressSanitizer; runs in the optimised build";

}  // namespace cloudsvc::test

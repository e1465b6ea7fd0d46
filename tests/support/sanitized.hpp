#pragma once
// Tests that repeat a check many times (random queries against a brute-force answer) run a tenth
// of their repetitions in the sanitizer build (make test-sanitize: about 20x slower than
// Release), where what matters is that each kind of query is made, not how many.

namespace flotsam::test {

#ifdef FLOTSAM_SANITIZE
constexpr bool sanitized = true;
#else
constexpr bool sanitized = false;
#endif

/// n repetitions, or n / 10 under the sanitizers.
constexpr int repetitions(int n) {
  return sanitized ? n / 10 : n;
}

}  // namespace flotsam::test

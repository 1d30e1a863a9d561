// Where code that ran a simulation catches an exception and goes on (a run destroying its machine
// and program, a command printing the error): in an AddressSanitizer build, clears the poison of
// the frames the exception unwound. ASan normally does so before every throw
// (__asan_handle_no_return), but after SystemC has switched stacks without telling it (Debian's
// libsystemc has no ASan fiber hooks) it no longer knows this thread's stack and skips that step
// ("ASan is ignoring requested
// __asan_handle_no_return"); the catch handler's next calls then reuse those frames' addresses and
// ASan reports their stale redzones as stack-buffer-overflows. Everything below the catching frame
// is dead once the exception is caught, so clearing it hides nothing live. No-op in other builds.
// Only on the thread's own stack, never inside a simulated process (a SystemC coroutine stack is
// smaller than the span cleared, which would reach memory that is not its own).
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/asan_interface.h>

#include <cstdint>
#endif

namespace network {

#if defined(__SANITIZE_ADDRESS__)
// Not inlined: its own frame is the lowest live one, and everything below it (1 MiB, far deeper
// than any frames a simulation's caller unwinds) is cleared.
__attribute__((noinline)) inline void forget_unwound_frames() {
  const auto here = reinterpret_cast<std::uintptr_t>(__builtin_frame_address(0));
  constexpr std::uintptr_t kSpan = std::uintptr_t(1) << 20;
  __asan_unpoison_memory_region(reinterpret_cast<void*>(here - kSpan), kSpan);
}
#else
inline void forget_unwound_frames() {}
#endif

}  // namespace network

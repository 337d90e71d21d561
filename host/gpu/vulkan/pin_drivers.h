#pragma once

namespace rtvk::gpu {

// In sanitizer builds, keeps the Vulkan driver and layer libraries (and the LLVM they load)
// mapped until exit. LeakSanitizer checks at exit, after the loader has unloaded them; their
// long-lived allocations would then show as "<unknown module>" and could not be told apart from
// rtvk's, nor suppressed by library (tests/lsan.supp). A no-op in normal builds.
void pin_driver_libraries();

}  // namespace rtvk::gpu

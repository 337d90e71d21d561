#include "pin_drivers.h"

#include "sanitizers.h"

#if RTVK_ASAN
#include <dlfcn.h>
#include <link.h>

#include <cstring>
#endif

namespace rtvk::gpu {

#if RTVK_ASAN
namespace {

int pin(struct dl_phdr_info* info, std::size_t, void*) {
  const char* name = info->dlpi_name;
  if (name && (std::strstr(name, "libvulkan_") || std::strstr(name, "VkLayer_") ||
               std::strstr(name, "libLLVM")))
    dlopen(name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);  // one more reference, never dropped
  return 0;
}

}  // namespace

void pin_driver_libraries() {
  dl_iterate_phdr(pin, nullptr);
}
#else
void pin_driver_libraries() {}
#endif

}  // namespace rtvk::gpu

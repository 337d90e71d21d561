# FindVolk: Debian's libvulkan-volk-dev ships only volk.h and volk.c, so build them here.
# Provides volk::volk, a static library that loads every Vulkan entry point at run time
# (VK_NO_PROTOTYPES: nothing links against libvulkan).
find_package(Vulkan REQUIRED)  # for Vulkan::Headers only
find_path(Volk_INCLUDE_DIR NAMES volk.h)
find_file(Volk_SOURCE NAMES volk.c HINTS ${Volk_INCLUDE_DIR} NO_DEFAULT_PATH)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Volk REQUIRED_VARS Volk_INCLUDE_DIR Volk_SOURCE)

if(Volk_FOUND AND NOT TARGET volk::volk)
  add_library(rtvk_volk STATIC ${Volk_SOURCE})
  set_target_properties(rtvk_volk PROPERTIES POSITION_INDEPENDENT_CODE ON)
  target_include_directories(rtvk_volk SYSTEM PUBLIC ${Volk_INCLUDE_DIR})
  target_compile_definitions(rtvk_volk PUBLIC VK_NO_PROTOTYPES)
  target_link_libraries(rtvk_volk PUBLIC Vulkan::Headers PRIVATE ${CMAKE_DL_LIBS})
  add_library(volk::volk ALIAS rtvk_volk)
endif()
mark_as_advanced(Volk_INCLUDE_DIR Volk_SOURCE)

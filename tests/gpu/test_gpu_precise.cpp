// The shaders round as the CPU does on every device: each float multiply, add and subtract they
// compile to is decorated NoContraction (GLSL `precise`), so no device may fuse a multiply into
// an add (NVIDIA does, unasked), and dot products are written out as glm computes them, since
// GLSL leaves the order and the fusing of its built-in dot() to the device.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <set>
#include <span>
#include <string>

#include "probe_shaders.h"
#include "shaders.h"

namespace rtvk {
namespace {

// SPIR-V opcodes and the one decoration this test reads (SPIR-V 1.x specification, 3.32 and 3.20).
constexpr std::uint32_t op_decorate = 71, op_fadd = 129, op_fsub = 131, op_fmul = 133,
                        op_vector_times_scalar = 142, op_dot = 148;
constexpr std::uint32_t decoration_no_contraction = 42;

struct arithmetic_census {
  std::map<std::string, int> undecorated;  // opcode name -> instructions without NoContraction
  int checked = 0;                         // multiplies, adds and subtracts seen
  int dots = 0;                            // OpDot instructions
};

arithmetic_census census(std::span<const std::uint32_t> spirv) {
  const std::map<std::uint32_t, std::string> names{{op_fadd, "OpFAdd"},
                                                   {op_fsub, "OpFSub"},
                                                   {op_fmul, "OpFMul"},
                                                   {op_vector_times_scalar, "OpVectorTimesScalar"}};
  std::set<std::uint32_t> no_contraction;
  std::map<std::uint32_t, std::uint32_t> opcode_of_result;
  for (std::size_t at = 5; at < spirv.size();) {  // after the 5-word header
    const std::uint32_t words = spirv[at] >> 16, opcode = spirv[at] & 0xffff;
    if (words == 0 || at + words > spirv.size()) {
      ADD_FAILURE() << "malformed SPIR-V at word " << at;
      break;
    }
    if (opcode == op_decorate && words >= 3 && spirv[at + 2] == decoration_no_contraction)
      no_contraction.insert(spirv[at + 1]);
    if (names.count(opcode) || opcode == op_dot) opcode_of_result[spirv[at + 2]] = opcode;
    at += words;
  }
  arithmetic_census c;
  for (const auto& [result, opcode] : opcode_of_result) {
    if (opcode == op_dot) {
      ++c.dots;
      continue;
    }
    ++c.checked;
    if (!no_contraction.count(result)) ++c.undecorated[names.at(opcode)];
  }
  return c;
}

std::string describe(const std::map<std::string, int>& undecorated) {
  std::string out;
  for (const auto& [name, n] : undecorated) out += " " + name + " x" + std::to_string(n);
  return out;
}

TEST(ShaderPrecision, EveryMultiplyAddAndSubtractIsNoContraction) {
  for (const auto& [name, spirv] : {std::pair{"render.comp", gpu::render_shader()},
                                    std::pair{"probe.comp", gpu::probe_shader()},
                                    std::pair{"hit_probe.comp", gpu::hit_probe_shader()},
                                    std::pair{"rng_probe.comp", gpu::rng_probe_shader()},
                                    std::pair{"world_probe.comp", gpu::world_probe_shader()},
                                    std::pair{"kernel_probe.comp", gpu::kernel_probe_shader()},
                                    std::pair{"pbr_probe.comp", gpu::pbr_probe_shader()},
                                    std::pair{"sobol_probe.comp", gpu::sobol_probe_shader()}}) {
    const arithmetic_census c = census(spirv);
    EXPECT_GT(c.checked, 0) << name << ": no float arithmetic found: is this SPIR-V?";
    EXPECT_TRUE(c.undecorated.empty())
        << name << ": without NoContraction:" << describe(c.undecorated);
    EXPECT_EQ(c.dots, 0) << name << ": dot() leaves its order to the device; use dot3";
  }
}

}  // namespace
}  // namespace rtvk

#pragma once
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "instance.h"
#include "physical_device.h"
#include "vk_handle.h"

namespace rtvk::gpu {

// Limits lower than the device's own, for tests that prove a limit is checked (0: the device's).
struct device_limit_caps {
  VkDeviceSize storage_range = 0;     // maxStorageBufferRange, bytes
  VkDeviceSize allocation_size = 0;   // maxMemoryAllocationSize, bytes
  std::uint32_t allocations = 0;      // maxMemoryAllocationCount
  VkDeviceSize heap_size = 0;         // every memory heap's size, bytes
  std::uint32_t workgroup_count = 0;  // maxComputeWorkGroupCount[0]
};

struct gpu_options {
  std::string device;  // --device: index, name substring, or empty for the default pick
  std::string device_source = "--device";            // where `device` came from, for error messages
  bool validate = false;                             // enable VK_LAYER_KHRONOS_validation
  std::chrono::milliseconds fence_timeout{120'000};  // longest wait for one submission
  device_limit_caps caps;                            // tests only
  // Presenting to a window (rtvk view): the instance extensions its window system needs, and
  // what makes the window's surface once the instance exists. The chosen device must then
  // present from a queue family that can also compute and draw (the viewer blits), which then
  // takes every submission, and gets VK_KHR_swapchain.
  std::vector<std::string> instance_extensions;
  std::function<VkSurfaceKHR(VkInstance)> make_surface;
};

// Semaphores a submission waits on and signals (presentation's image acquisition and release).
struct submit_sync {
  VkSemaphore wait = VK_NULL_HANDLE;    // waited on before `wait_stage`
  VkPipelineStageFlags wait_stage = 0;  // the stage that waits
  VkSemaphore signal = VK_NULL_HANDLE;  // signalled when the submission completes
};

// One chosen device with its queue, command pool and fence: everything a render submits with.
class gpu_context {
 public:
  explicit gpu_context(const gpu_options& options);
  ~gpu_context();
  gpu_context(const gpu_context&) = delete;
  gpu_context& operator=(const gpu_context&) = delete;

  const device_info& device() const { return devices_[chosen_]; }
  // A submission timed out or the device was lost: work may still be running on it, so objects
  // it may touch must not be destroyed (their owners give their handles up instead).
  bool lost() const { return lost_; }
  VkDevice vk() const { return device_.get(); }
  VkInstance instance() const { return instance_.get(); }
  VkQueue queue() const { return queue_; }
  // The window's surface, when made with options.make_surface; else VK_NULL_HANDLE.
  VkSurfaceKHR surface() const { return surface_.get(); }
  std::uint32_t validation_messages() const { return instance_.validation_messages(); }
  bool validating() const { return instance_.validating(); }
  // Throws when the validation layer has reported anything (printed above): a validated run
  // with problems must not pass. `consequence` ends the message ("; no image written").
  void check_validation(const std::string& consequence = "") const;

  // A memory type allowed by type_bits with all `required` flags, preferring one that also has
  // `preferred` and then one without `avoided`. Throws when there is none.
  std::uint32_t memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags required,
                            VkMemoryPropertyFlags preferred = 0,
                            VkMemoryPropertyFlags avoided = 0) const;
  // What this process may still allocate in each memory heap, bytes: VK_EXT_memory_budget's
  // budget less what the process uses where the device has it (asked anew each call: other
  // processes change it), else the heap's size. `from_budget` says which.
  struct heap_room {
    VkDeviceSize bytes;  // may still be allocated
    bool from_budget;    // VK_EXT_memory_budget's figure, not the heap's size
  };
  std::vector<heap_room> heap_rooms() const;
  bool memory_type_has(std::uint32_t type, VkMemoryPropertyFlags flags) const;
  const VkPhysicalDeviceMemoryProperties& memory_properties() const { return memory_; }

  // Records one command buffer, submits it and waits for the fence. A wait longer than the
  // timeout, or a lost device, throws vk_error naming the device; the context is then unusable.
  void submit_and_wait(const std::function<void(VkCommandBuffer)>& record);

  // Submissions in flight together: up to `submission_slots` recorded and queued before the host
  // waits for the oldest, so the device has the next one while the host reads the last one.
  // Tickets count submissions from 1; a ticket's slot is (ticket % submission_slots), and its
  // command buffer is reused by the submission `submission_slots` later.
  static constexpr std::uint64_t submission_slots = 2;
  // Records and submits; first waits for the submission that last used the slot, if any.
  std::uint64_t submit(const std::function<void(VkCommandBuffer)>& record,
                       const submit_sync& sync = {});
  // The ticket the next submit() returns (for recording per-slot queries).
  std::uint64_t next_ticket() const { return submitted_ + 1; }
  // Waits for submission `ticket` and every one before it, as submit_and_wait does.
  void wait(std::uint64_t ticket);
  // Waits for everything submitted (no timeout error is thrown; for clean-up on error paths).
  void wait_all() noexcept;

 private:
  gpu_options options_;                        // as given
  vulkan_instance instance_;                   // destroyed last
  unique_surface surface_;                     // the window's, when presenting
  std::vector<device_info> devices_;           // every device the instance sees
  std::size_t chosen_ = 0;                     // index into devices_
  VkPhysicalDeviceMemoryProperties memory_{};  // of the chosen device
  unique_device device_;                       // logical device
  VkQueue queue_ = VK_NULL_HANDLE;             // first queue of the compute family
  unique_command_pool pool_;                   // command buffers for submissions
  struct slot {
    VkCommandBuffer cb = VK_NULL_HANDLE;  // freed with pool_
    unique_fence fence;                   // signalled when its submission completes
    std::uint64_t ticket = 0;             // the submission it holds; 0: none
  };
  slot slots_[submission_slots];  // ring of submissions
  std::uint64_t submitted_ = 0;   // tickets handed out
  std::uint64_t completed_ = 0;   // every ticket up to this one is known complete
  bool lost_ = false;             // a wait timed out or the device was lost
};

}  // namespace rtvk::gpu

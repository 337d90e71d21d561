#pragma once
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
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
  std::uint64_t primitives = 0;       // maxPrimitiveCount of acceleration structures
};

struct gpu_options {
  std::string device;  // --device: index, name substring, or empty for the default pick
  std::string device_source = "--device";            // where `device` came from, for error messages
  bool validate = false;                             // enable VK_LAYER_KHRONOS_validation
  std::chrono::milliseconds fence_timeout{120'000};  // longest wait for one submission
  device_limit_caps caps;                            // tests only
  // Enable what the device offers of hardware ray tracing (acceleration structures, ray queries,
  // ray-tracing pipelines, and the extensions they need): --accel rt-query, rt-pipeline, auto.
  bool ray_tracing = false;
  // Presenting to a window (rtvk view): the instance extensions its window system needs, and
  // what makes the window's surface once the instance exists. The chosen device must then
  // present from a queue family that can also compute and draw (the viewer blits and composes
  // its overlay there), and gets VK_KHR_swapchain. Renders stay on the compute family: where
  // that is another family (a dedicated compute queue), the context has two queues.
  std::vector<std::string> instance_extensions;
  std::function<VkSurfaceKHR(VkInstance)> make_surface;
};

// The two queues a context may have: renders go to `compute` (a compute-only family where the
// device has one, so a long render does not hold up the desktop's drawing), a window's frames to
// `presenting` (graphics, compute and present). Without a window, or where one family does both,
// they are the same queue.
enum class queue_role { compute, presenting };

// Semaphores a submission waits on and signals (presentation's image acquisition and release).
struct submit_sync {
  VkSemaphore wait = VK_NULL_HANDLE;    // waited on before `wait_stage`
  VkPipelineStageFlags wait_stage = 0;  // the stage that waits
  VkSemaphore signal = VK_NULL_HANDLE;  // signalled when the submission completes
};

// One chosen device with its queues, command pools and fences: everything a render submits with.
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
  VkQueue queue(queue_role role = queue_role::compute) const { return lane(role).queue; }
  std::uint32_t queue_family(queue_role role = queue_role::compute) const {
    return lane(role).family;
  }
  // Whether the presenting queue is another family's than the compute queue: then buffers both
  // use are made with shared_families() (concurrent sharing), and the viewer orders the two
  // queues' work (host/view/viewer.cpp, session::render_batch).
  bool split_queues() const { return presenting_ != nullptr; }
  // The families a buffer used by both queues is shared between; empty when they are one.
  std::vector<std::uint32_t> shared_families() const;
  // The window's surface, when made with options.make_surface; else VK_NULL_HANDLE.
  VkSurfaceKHR surface() const { return surface_.get(); }
  // What of hardware ray tracing the device was created with (gpu_options::ray_tracing and
  // the device offering it): the extensions and features are enabled.
  bool ray_queries() const { return ray_queries_; }
  const device_limit_caps& caps() const { return options_.caps; }
  bool ray_tracing_pipelines() const { return ray_tracing_pipelines_; }
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

  // Records one command buffer, submits it to the compute queue and waits for the fence. A wait
  // longer than the timeout, or a lost device, throws vk_error naming the device; the context is
  // then unusable.
  void submit_and_wait(const std::function<void(VkCommandBuffer)>& record);

  // Submissions in flight together: up to `submission_slots` recorded and queued before the host
  // waits for the oldest, so the device has the next one while the host reads the last one.
  // Tickets count a queue's submissions from 1; a ticket's slot is (ticket % submission_slots),
  // and its command buffer is reused by the submission `submission_slots` later.
  static constexpr std::uint64_t submission_slots = 2;
  // Records and submits to the role's queue; first waits for the submission that last used the
  // slot, if any.
  std::uint64_t submit(const std::function<void(VkCommandBuffer)>& record,
                       const submit_sync& sync = {}, queue_role role = queue_role::compute);
  // The ticket the next submit() to the role's queue returns (for recording per-slot queries).
  std::uint64_t next_ticket(queue_role role = queue_role::compute) const {
    return lane(role).submitted + 1;
  }
  // Waits for submission `ticket` of the role's queue and every one before it there, as
  // submit_and_wait does.
  void wait(std::uint64_t ticket, queue_role role = queue_role::compute);
  // Waits for everything submitted to either queue (no timeout error is thrown; for clean-up on
  // error paths).
  void wait_all() noexcept;

  // Says that the command buffer being recorded runs a pipeline for the first time (the
  // pipelines' bind() calls it). lavapipe compiles a pipeline's shaders inside the first
  // submission that runs them, not in vkCreate*Pipelines as GPU drivers do: a second or two for
  // the books' shaders on Mesa 22.3, over two minutes for the PBR shaders on Mesa 25, several
  // times that on a loaded machine. On lavapipe, whose loops cannot run away (its loop limit),
  // that submission's wait gets first_run_allowance beyond --gpu-timeout, so that a compile is
  // not taken for a hung device.
  void note_first_run() const { first_run_recorded_ = true; }
  static constexpr std::chrono::minutes first_run_allowance{30};

 private:
  gpu_options options_;                        // as given
  vulkan_instance instance_;                   // destroyed last
  unique_surface surface_;                     // the window's, when presenting
  std::vector<device_info> devices_;           // every device the instance sees
  std::size_t chosen_ = 0;                     // index into devices_
  VkPhysicalDeviceMemoryProperties memory_{};  // of the chosen device
  unique_device device_;                       // logical device
  struct slot {
    VkCommandBuffer cb = VK_NULL_HANDLE;  // freed with its lane's pool
    unique_fence fence;                   // signalled when its submission completes
    std::uint64_t ticket = 0;             // the submission it holds; 0: none
    bool first_run = false;               // it runs some pipeline for the first time
  };
  // One queue with its command pool and ring of submissions.
  struct queue_lane {
    std::uint32_t family = 0;        // queue family index
    VkQueue queue = VK_NULL_HANDLE;  // the family's first queue
    unique_command_pool pool;        // command buffers for submissions
    slot slots[submission_slots];    // ring of submissions
    std::uint64_t submitted = 0;     // tickets handed out
    std::uint64_t completed = 0;     // every ticket up to this one is known complete
  };
  void open_lane(queue_lane& l, std::uint32_t family);
  void wait_all(queue_lane& l) noexcept;
  void abandon(queue_lane& l) noexcept;
  queue_lane& lane(queue_role role) {
    return role == queue_role::presenting && presenting_ ? *presenting_ : compute_;
  }
  const queue_lane& lane(queue_role role) const {
    return role == queue_role::presenting && presenting_ ? *presenting_ : compute_;
  }
  queue_lane compute_;                       // renders (and everything, without a split)
  std::unique_ptr<queue_lane> presenting_;   // a window's frames, when another family's
  bool lost_ = false;                        // a wait timed out or the device was lost
  mutable bool first_run_recorded_ = false;  // note_first_run() since submit() began recording
  bool ray_queries_ = false;                 // VK_KHR_ray_query enabled
  bool ray_tracing_pipelines_ = false;       // VK_KHR_ray_tracing_pipeline enabled
};

}  // namespace rtvk::gpu

// VkResult names and the check of a Vulkan call's result (see errors.hpp).
#include "errors.hpp"

namespace vkref::detail {

std::string resultName(VkResult result) {
  switch (result) {
#define VKREF_RESULT(name) \
  case name:               \
    return #name;
    VKREF_RESULT(VK_SUCCESS)
    VKREF_RESULT(VK_NOT_READY)
    VKREF_RESULT(VK_TIMEOUT)
    VKREF_RESULT(VK_INCOMPLETE)
    VKREF_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
    VKREF_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    VKREF_RESULT(VK_ERROR_INITIALIZATION_FAILED)
    VKREF_RESULT(VK_ERROR_DEVICE_LOST)
    VKREF_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
    VKREF_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
    VKREF_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
    VKREF_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
    VKREF_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
    VKREF_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
    VKREF_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
    VKREF_RESULT(VK_ERROR_FRAGMENTED_POOL)
    VKREF_RESULT(VK_ERROR_UNKNOWN)
    VKREF_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
    VKREF_RESULT(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    VKREF_RESULT(VK_ERROR_FRAGMENTATION)
    VKREF_RESULT(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    VKREF_RESULT(VK_PIPELINE_COMPILE_REQUIRED)
    VKREF_RESULT(VK_ERROR_VALIDATION_FAILED_EXT)
    VKREF_RESULT(VK_ERROR_INVALID_SHADER_NV)
#undef VKREF_RESULT
    default:
      return "VkResult(" + std::to_string(static_cast<int>(result)) + ")";
  }
}

softraster::Status check(VkResult result, const char* call) {
  if (result == VK_SUCCESS) return {};
  return softraster::Status::error(std::string(call) + ": " + resultName(result));
}

}  // namespace vkref::detail

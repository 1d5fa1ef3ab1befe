// vkref errors: the names of VkResult values and the one check every Vulkan call's result goes
// through, turning it into a softraster::Status ("vkCreateBuffer: VK_ERROR_OUT_OF_DEVICE_MEMORY").
// Deliberately no exceptions, no logging and no retries: a failed call becomes one line of text,
// which the caller prefixes with what it was doing.
#pragma once

#include <softraster/status.hpp>

#include <vulkan/vulkan.h>

#include <string>

namespace vkref::detail {

// "VK_ERROR_OUT_OF_DEVICE_MEMORY", or "VkResult(-13)" for a value this list does not name.
std::string resultName(VkResult result);

// Success for VK_SUCCESS; otherwise the error "call: RESULT_NAME".
softraster::Status check(VkResult result, const char* call);

}  // namespace vkref::detail

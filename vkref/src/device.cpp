// vkref device (see device.hpp): instance, messenger, device pick, features and queue.
// With validation on, an error the layer reports also aborts the offending call (see
// collectMessage), so invalid input fails as an error value instead of reaching the driver.
#include "device.hpp"

#include "errors.hpp"

#include <algorithm>
#include <cstring>
#include <utility>

namespace vkref::detail {
namespace {

using softraster::Status;

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

// Returning VK_TRUE for an error makes the layer abort the offending call with
// VK_ERROR_VALIDATION_FAILED_EXT instead of passing it on: invalid input (malformed SPIR-V, say)
// then fails cleanly rather than crashing the layer or the driver further down.
VKAPI_ATTR VkBool32 VKAPI_CALL collectMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                              VkDebugUtilsMessageTypeFlagsEXT,
                                              const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  static_cast<Device*>(user)->addMessage(data ? data->pMessage : nullptr);
  return severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? VK_TRUE : VK_FALSE;
}

}  // namespace

softraster::Result<std::unique_ptr<Device>> Device::create(const DeviceOptions& options) {
  std::unique_ptr<Device> device(new Device);
  if (Status s = device->createInstance(options.validation); !s) return s;
  if (Status s = device->pickDevice(options.deviceName); !s) return s;
  if (Status s = device->createDevice(); !s) return s;
  return device;
}

Device::~Device() {
  if (device) {
    vkDeviceWaitIdle(device);
    vkDestroyDevice(device, nullptr);
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
  }
  if (instance_) vkDestroyInstance(instance_, nullptr);
}

std::vector<std::string> Device::messages() const {
  const std::lock_guard lock(messagesMutex_);
  return messages_;
}

void Device::addMessage(const char* text) {
  const std::lock_guard lock(messagesMutex_);
  messages_.emplace_back(text ? text : "");
}

Status Device::createInstance(bool validation) {
  std::vector<const char*> layers, extensions;
  if (validation) {
    std::uint32_t count = 0;
    if (Status s = check(vkEnumerateInstanceLayerProperties(&count, nullptr), "vkEnumerateInstanceLayerProperties");
        !s)
      return s;
    std::vector<VkLayerProperties> available(count);
    if (Status s = check(vkEnumerateInstanceLayerProperties(&count, available.data()),
                         "vkEnumerateInstanceLayerProperties");
        !s)
      return s;
    bool found = false;
    for (std::uint32_t i = 0; i < count; ++i) found = found || std::strcmp(available[i].layerName, kValidationLayer) == 0;
    if (!found)
      return Status::error("validation requested but VK_LAYER_KHRONOS_validation is not available "
                           "(is vulkan-validationlayers installed?)");
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }

  const VkApplicationInfo app{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                              .pApplicationName = "vkref",
                              .pEngineName = "vkref",
                              .apiVersion = VK_API_VERSION_1_3};
  // Chained into the instance create info too, so instance creation and destruction are covered.
  const VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
      .sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
      .messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
      .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT,
      .pfnUserCallback = &collectMessage,
      .pUserData = this};
  const VkInstanceCreateInfo info{.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
                                  .pNext = validation ? &messengerInfo : nullptr,
                                  .pApplicationInfo = &app,
                                  .enabledLayerCount = static_cast<std::uint32_t>(layers.size()),
                                  .ppEnabledLayerNames = layers.data(),
                                  .enabledExtensionCount = static_cast<std::uint32_t>(extensions.size()),
                                  .ppEnabledExtensionNames = extensions.data()};
  const VkResult r = vkCreateInstance(&info, nullptr, &instance_);
  if (r == VK_ERROR_INCOMPATIBLE_DRIVER)
    return Status::error("no Vulkan driver found (vkCreateInstance: VK_ERROR_INCOMPATIBLE_DRIVER; "
                         "is mesa-vulkan-drivers installed?)");
  if (Status s = check(r, "vkCreateInstance"); !s) return s;
  if (!validation) return {};
  auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
  if (!create) return Status::error("vkCreateDebugUtilsMessengerEXT is not available");
  return check(create(instance_, &messengerInfo, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
}

Status Device::pickDevice(const std::string& wanted) {
  std::uint32_t count = 0;
  if (Status s = check(vkEnumeratePhysicalDevices(instance_, &count, nullptr), "vkEnumeratePhysicalDevices"); !s)
    return s;
  std::vector<VkPhysicalDevice> devices(count);
  if (Status s = check(vkEnumeratePhysicalDevices(instance_, &count, devices.data()), "vkEnumeratePhysicalDevices");
      !s)
    return s;
  devices.resize(count);
  if (devices.empty()) return Status::error("no Vulkan device found (is mesa-vulkan-drivers installed?)");

  std::string available;
  for (VkPhysicalDevice candidate : devices) {
    VkPhysicalDeviceDriverProperties driver{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 properties{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    vkGetPhysicalDeviceProperties(candidate, &properties.properties);
    if (properties.properties.apiVersion >= VK_API_VERSION_1_2) {  // driver properties are core from 1.2
      properties.pNext = &driver;
      vkGetPhysicalDeviceProperties2(candidate, &properties);
    }
    const std::string candidateName = properties.properties.deviceName;
    const bool match = wanted.empty() ? driver.driverID == VK_DRIVER_ID_MESA_LLVMPIPE
                                      : candidateName.find(wanted) != std::string::npos;
    if (match) {
      physicalDevice_ = candidate;
      name = candidateName;
      limits = properties.properties.limits;
      if (properties.properties.apiVersion < VK_API_VERSION_1_3)
        return Status::error("Vulkan device '" + name + "' supports Vulkan " +
                             std::to_string(VK_API_VERSION_MAJOR(properties.properties.apiVersion)) + "." +
                             std::to_string(VK_API_VERSION_MINOR(properties.properties.apiVersion)) +
                             "; vkref needs 1.3");
      return {};
    }
    available += (available.empty() ? "" : ", ") + candidateName;
  }
  const std::string what = wanted.empty() ? "lavapipe (llvmpipe)" : "'" + wanted + "'";
  return Status::error("no Vulkan device matches " + what + " (available: " + available + ")");
}

Status Device::createDevice() {
  VkPhysicalDeviceVulkan13Features supported{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  VkPhysicalDeviceFeatures2 features2{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &supported};
  vkGetPhysicalDeviceFeatures2(physicalDevice_, &features2);
  if (!supported.dynamicRendering || !supported.synchronization2)
    return Status::error("Vulkan device '" + name + "' lacks dynamicRendering or synchronization2");

  const auto supports = [&](VkFormat format, VkFormatFeatureFlags needed) {
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(physicalDevice_, format, &properties);
    return (properties.optimalTilingFeatures & needed) == needed;
  };
  constexpr VkFormatFeatureFlags colourNeeds = VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT |
                                               VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT |
                                               VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT;
  for (std::size_t f = 0; f < std::size(kColourFormats); ++f) colourFormatUsable[f] = supports(kColourFormats[f], colourNeeds);
  if (!colourFormatUsable[0])
    return Status::error("Vulkan device '" + name + "' cannot render to R8G8B8A8_UNORM, blend, sample and copy it");
  for (std::size_t f = 0; f < std::size(kDepthFormats); ++f)
    depthFormatUsable[f] =
        supports(kDepthFormats[f], VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT);
  // Optional core features scenes may use: enabled when the device has them, else draws needing
  // them are rejected by checkDraw (pipelines.hpp).
  features.depthClamp = features2.features.depthClamp;
  features.depthBiasClamp = features2.features.depthBiasClamp;
  features.wideLines = features2.features.wideLines;
  features.fillModeNonSolid = features2.features.fillModeNonSolid;
  features.largePoints = features2.features.largePoints;
  features.geometryShader = features2.features.geometryShader;  // the adjacency topologies need it
  features.logicOp = features2.features.logicOp;
  // Several colour attachments blended differently (PipelineState::moreBlend) need it
  // (VUID-VkPipelineColorBlendStateCreateInfo-pAttachments-00605; lavapipe has it).
  features.independentBlend = features2.features.independentBlend;
  features.alphaToOne = features2.features.alphaToOne;
  features.sampleRateShading = features2.features.sampleRateShading;

  // VK_EXT_line_rasterization (Bresenham and stippled lines) and VK_EXT_provoking_vertex
  // (provoking vertex last): enabled with the features vkref uses when the device has them.
  std::uint32_t extensionCount = 0;
  vkEnumerateDeviceExtensionProperties(physicalDevice_, nullptr, &extensionCount, nullptr);
  std::vector<VkExtensionProperties> extensions(extensionCount);
  vkEnumerateDeviceExtensionProperties(physicalDevice_, nullptr, &extensionCount, extensions.data());
  const auto hasExtension = [&](const char* name) {
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
  };
  const bool hasLineRasterization = hasExtension(VK_EXT_LINE_RASTERIZATION_EXTENSION_NAME);
  const bool hasProvokingVertex = hasExtension(VK_EXT_PROVOKING_VERTEX_EXTENSION_NAME);
  VkPhysicalDeviceLineRasterizationFeaturesEXT lineFeatures{
      .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_LINE_RASTERIZATION_FEATURES_EXT};
  VkPhysicalDeviceProvokingVertexFeaturesEXT provokingFeatures{
      .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROVOKING_VERTEX_FEATURES_EXT};
  if (hasLineRasterization) {
    VkPhysicalDeviceFeatures2 query{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &lineFeatures};
    vkGetPhysicalDeviceFeatures2(physicalDevice_, &query);
    bresenhamLines = lineFeatures.bresenhamLines == VK_TRUE;
    rectangularLines = lineFeatures.rectangularLines == VK_TRUE;
    stippledRectangularLines = lineFeatures.stippledRectangularLines == VK_TRUE;
    stippledBresenhamLines = lineFeatures.stippledBresenhamLines == VK_TRUE;
  }
  if (hasProvokingVertex) {
    VkPhysicalDeviceFeatures2 query{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &provokingFeatures};
    vkGetPhysicalDeviceFeatures2(physicalDevice_, &query);
    provokingVertexLast = provokingFeatures.provokingVertexLast == VK_TRUE;
  }

  std::uint32_t familyCount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice_, &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice_, &familyCount, families.data());
  queueFamily = familyCount;
  for (std::uint32_t i = 0; i < familyCount && queueFamily == familyCount; ++i)
    if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) queueFamily = i;
  if (queueFamily == familyCount) return Status::error("Vulkan device '" + name + "' has no graphics queue");

  const float priority = 1.0f;
  const VkDeviceQueueCreateInfo queueInfo{.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
                                          .queueFamilyIndex = queueFamily,
                                          .queueCount = 1,
                                          .pQueuePriorities = &priority};
  VkPhysicalDeviceProvokingVertexFeaturesEXT enabledProvoking{
      .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROVOKING_VERTEX_FEATURES_EXT,
      .provokingVertexLast = VK_TRUE};
  const bool lines = bresenhamLines || rectangularLines || stippledRectangularLines || stippledBresenhamLines;
  VkPhysicalDeviceLineRasterizationFeaturesEXT enabledLines{
      .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_LINE_RASTERIZATION_FEATURES_EXT,
      .pNext = provokingVertexLast ? &enabledProvoking : nullptr,
      .rectangularLines = rectangularLines ? VK_TRUE : VK_FALSE,
      .bresenhamLines = bresenhamLines ? VK_TRUE : VK_FALSE,
      .stippledRectangularLines = stippledRectangularLines ? VK_TRUE : VK_FALSE,
      .stippledBresenhamLines = stippledBresenhamLines ? VK_TRUE : VK_FALSE};
  void* chain = lines ? static_cast<void*>(&enabledLines)
                      : (provokingVertexLast ? static_cast<void*>(&enabledProvoking) : nullptr);
  VkPhysicalDeviceVulkan13Features enabled{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
                                           .pNext = chain,
                                           .synchronization2 = VK_TRUE,
                                           .dynamicRendering = VK_TRUE};
  std::vector<const char*> enabledExtensions;
  if (lines) enabledExtensions.push_back(VK_EXT_LINE_RASTERIZATION_EXTENSION_NAME);
  if (provokingVertexLast) enabledExtensions.push_back(VK_EXT_PROVOKING_VERTEX_EXTENSION_NAME);
  const VkDeviceCreateInfo info{.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
                                .pNext = &enabled,
                                .queueCreateInfoCount = 1,
                                .pQueueCreateInfos = &queueInfo,
                                .enabledExtensionCount = static_cast<std::uint32_t>(enabledExtensions.size()),
                                .ppEnabledExtensionNames = enabledExtensions.data(),
                                .pEnabledFeatures = &features};
  if (Status s = check(vkCreateDevice(physicalDevice_, &info, nullptr, &device), "vkCreateDevice"); !s) return s;
  vkGetDeviceQueue(device, queueFamily, 0, &queue);
  vkGetPhysicalDeviceMemoryProperties(physicalDevice_, &memory);
  return {};
}

}  // namespace vkref::detail

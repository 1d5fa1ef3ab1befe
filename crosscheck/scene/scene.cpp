// Scene file loading and validation (see scene.hpp and scenes/README.md).
#include "scene/scene.hpp"

#include "scene/camera.hpp"
#include "scene/normals.hpp"
#include "scene/obj_mesh.hpp"
#include "scene/input_file.hpp"
#include "scene/texture_file.hpp"

#include <softraster/limits.hpp>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <tuple>

namespace crosscheck {
namespace {

using nlohmann::json;
using Limits = softraster::DeviceLimits;  // lavapipe's, which the scene format follows

// Limits of the scene format (scenes/README.md, "Limits"): generous, but no input exceeds them
// unchecked. 8192 x 8192 with 4 samples is the largest frame (about 2 GiB in both renderers).
constexpr std::uint64_t kMaxFramebufferSize = 8192;
constexpr std::size_t kMaxDraws = 100'000;
constexpr std::size_t kMaxSceneVertices = 16'000'000;  // over all draws: positions, or indices when indexed

// A failure at a place in the scene file; turned into "FILE: PLACE: message".
struct SceneError : std::runtime_error {
  SceneError(std::string place, const std::string& message) : std::runtime_error(message), place(std::move(place)) {}
  std::string place;
};

std::string placeOf(const std::string& parent, const std::string& key) { return parent + "/" + key; }

softraster::Mat4 roundedToFloat(const glm::dmat4& m) {
  softraster::Mat4 out;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) out.at(r, c) = static_cast<float>(m[c][r]);
  }
  return out;
}

softraster::Vec4 roundedToFloat(const glm::dvec4& v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), static_cast<float>(v.w)};
}

// The inverse transpose of m's upper 3x3, as a Mat4 whose columns' xyz hold it.
softraster::Mat4 normalMatrix(const glm::dmat4& m) {
  const glm::dmat3 n = glm::inverseTranspose(glm::dmat3(m));
  glm::dmat4 out(0.0);
  for (int c = 0; c < 3; ++c) out[c] = glm::dvec4(n[c], 0.0);
  return roundedToFloat(out);
}

// Vulkan's VkViewport rules with lavapipe's limits, quoted in the error (a width or height of 0
// is refused here, though softraster's library API reads it as "the whole framebuffer"). A
// negative height is Vulkan 1.1's y flip.
void checkViewport(const softraster::Viewport& v, const std::string& place) {
  if (!(v.width > 0)) {
    throw SceneError(placeOf(place, "width"), "must be greater than 0 (VUID-VkViewport-width-01770: \"width must be "
                                              "greater than 0.0\")");
  }
  if (v.height == 0) {
    throw SceneError(placeOf(place, "height"), "must not be 0 (Vulkan 1.0's VkViewport rule \"height must be greater "
                                               "than 0.0\" became, with VK_KHR_maintenance1, a negative height for a y "
                                               "flip, never an empty viewport); give a negative height to flip y");
  }
  if (v.width > Limits::kMaxViewportDimension || std::fabs(v.height) > Limits::kMaxViewportDimension) {
    throw SceneError(place, "width and |height| must be at most 16384, the device's maxViewportDimensions "
                            "(VUID-VkViewport-width-01771, VUID-VkViewport-height-01773: \"The absolute value of "
                            "height must be less than or equal to VkPhysicalDeviceLimits::maxViewportDimensions[1]\")");
  }
  if (v.x < Limits::kViewportBoundsMin || v.y < Limits::kViewportBoundsMin || v.y > Limits::kViewportBoundsMax ||
      v.x + v.width > Limits::kViewportBoundsMax || v.y + v.height < Limits::kViewportBoundsMin ||
      v.y + v.height > Limits::kViewportBoundsMax) {
    throw SceneError(place, "must lie within the device's viewportBoundsRange [-32768, 32768] (Vulkan: \"x must "
                            "be greater than or equal to viewportBoundsRange[0]\", \"(x + width) must be less than "
                            "or equal to viewportBoundsRange[1]\", likewise y and y + height, either way round)");
  }
  if (!(v.minDepth >= 0 && v.minDepth <= 1 && v.maxDepth >= 0 && v.maxDepth <= 1)) {
    throw SceneError(place, "min_depth and max_depth must be in [0, 1]");
  }
}

bool isFinite(const softraster::Mat4& m) {
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      if (!std::isfinite(m.at(r, c))) return false;
    }
  }
  return true;
}

// Rejects keys the format does not know, so a typo is an error instead of a silent default.
void checkKeys(const json& object, const std::string& place, std::initializer_list<const char*> known) {
  if (!object.is_object()) throw SceneError(place, "expected an object");
  const std::set<std::string> allowed(known.begin(), known.end());
  for (const auto& [key, value] : object.items()) {
    if (!allowed.count(key)) {
      std::string list;
      for (const char* k : known) list += std::string(list.empty() ? "" : ", ") + k;
      throw SceneError(placeOf(place, key), "unknown field (known: " + list + ")");
    }
  }
}

double readNumber(const json& value, const std::string& place) {
  if (!value.is_number()) throw SceneError(place, "expected a number");
  return value.get<double>();
}

// A vertex coordinate: a number, or "nan", "inf" or "-inf" (JSON has no literals for them),
// so scenes can test how the pipeline drops such vertices.
float readCoordinate(const json& value, const std::string& place) {
  if (value.is_string()) {
    const std::string text = value.get<std::string>();
    if (text == "nan") return std::numeric_limits<float>::quiet_NaN();
    if (text == "inf") return std::numeric_limits<float>::infinity();
    if (text == "-inf") return -std::numeric_limits<float>::infinity();
    throw SceneError(place, "expected a number, \"nan\", \"inf\" or \"-inf\"");
  }
  return static_cast<float>(readNumber(value, place));
}

double readNumber(const json& object, const char* key, const std::string& place, double fallback) {
  return object.contains(key) ? readNumber(object[key], placeOf(place, key)) : fallback;
}

// A whole number in [0, max]; checked before any narrowing, so 4294967297 is an error, not 1.
std::uint64_t readCount(const json& object, const char* key, const std::string& place, std::uint64_t fallback,
                        std::uint64_t max = std::numeric_limits<std::uint64_t>::max()) {
  if (!object.contains(key)) return fallback;
  const json& v = object[key];
  const std::string at = placeOf(place, key);
  if (!v.is_number_integer() || (!v.is_number_unsigned() && v.get<std::int64_t>() < 0)) {
    throw SceneError(at, "expected a non-negative integer");
  }
  const std::uint64_t n = v.get<std::uint64_t>();
  if (n > max) throw SceneError(at, std::to_string(n) + " is more than " + std::to_string(max));
  return n;
}

// A number that is finite as a float (every float in the scene format is rounded to float once).
float readFloat(const json& object, const char* key, const std::string& place, float fallback) {
  if (!object.contains(key)) return fallback;
  const double v = readNumber(object[key], placeOf(place, key));
  const auto f = static_cast<float>(v);
  if (!std::isfinite(f)) throw SceneError(placeOf(place, key), "must be a finite number within float range");
  return f;
}

bool readBool(const json& object, const char* key, const std::string& place, bool fallback) {
  if (!object.contains(key)) return fallback;
  if (!object[key].is_boolean()) throw SceneError(placeOf(place, key), "expected true or false");
  return object[key].get<bool>();
}

std::string readString(const json& object, const char* key, const std::string& place, const std::string& fallback) {
  if (!object.contains(key)) return fallback;
  if (!object[key].is_string()) throw SceneError(placeOf(place, key), "expected a string");
  return object[key].get<std::string>();
}

std::vector<double> readNumbers(const json& value, const std::string& place, std::size_t minCount, std::size_t maxCount) {
  if (!value.is_array() || value.size() < minCount || value.size() > maxCount) {
    throw SceneError(place, minCount == maxCount ? "expected an array of " + std::to_string(minCount) + " numbers"
                                                 : "expected an array of " + std::to_string(minCount) + " to " +
                                                       std::to_string(maxCount) + " numbers");
  }
  std::vector<double> out;
  for (std::size_t i = 0; i < value.size(); ++i) out.push_back(readNumber(value[i], placeOf(place, std::to_string(i))));
  return out;
}

std::array<double, 3> readVec3(const json& object, const char* key, const std::string& place, std::array<double, 3> fallback) {
  if (!object.contains(key)) return fallback;
  const auto v = readNumbers(object[key], placeOf(place, key), 3, 3);
  return {v[0], v[1], v[2]};
}

// A colour is [r, g, b] or [r, g, b, a], floats in [0, 1]; alpha defaults to 1.
// What a colour may hold: [0, 1] for a UNORM or sRGB target (they clamp), any finite float for a
// float target (it keeps values beyond 1 and below 0).
enum class ColourRange { Unit, Finite };

ColourRange colourRange(softraster::ColourFormat format) {
  return softraster::isFloat(format) ? ColourRange::Finite : ColourRange::Unit;
}

softraster::Vec4 readColour(const json& value, const std::string& place, ColourRange range = ColourRange::Unit) {
  const auto v = readNumbers(value, place, 3, 4);
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (range == ColourRange::Unit && !(v[i] >= 0 && v[i] <= 1))
      throw SceneError(placeOf(place, std::to_string(i)), "must be in [0, 1]");
    if (!(std::fabs(v[i]) <= std::numeric_limits<float>::max()))
      throw SceneError(placeOf(place, std::to_string(i)), "must be a finite float");
  }
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]),
          v.size() == 4 ? static_cast<float>(v[3]) : 1.0f};
}

template <class Enum>
Enum readEnum(const json& object, const char* key, const std::string& place, Enum fallback,
              const std::vector<std::pair<const char*, Enum>>& names) {
  if (!object.contains(key)) return fallback;
  const std::string value = readString(object, key, place, "");
  std::string list;
  for (const auto& [name, e] : names) {
    if (value == name) return e;
    list += std::string(list.empty() ? "" : ", ") + name;
  }
  throw SceneError(placeOf(place, key), "'" + value + "' is not one of " + list);
}

// The row of shaders/shading_models.hpp named by "shading" (default: kDefaultShadingModel).
const shaders::ShadingModel* readShadingModel(const json& d, const std::string& place) {
  const std::string name = readString(d, "shading", place, std::string(shaders::kDefaultShadingModel));
  if (const shaders::ShadingModel* model = shaders::findShadingModel(name)) return model;
  std::string list;
  for (const shaders::ShadingModel& model : shaders::shadingModels()) {
    list += (list.empty() ? "" : ", ") + std::string(model.name);
  }
  throw SceneError(placeOf(place, "shading"), "'" + name + "' is not one of " + list);
}

// The camera's settings (its type and parameters, defaults filled in) and its matrices.
CameraMatrices readCamera(const json& camera, const std::string& place, int width, int height, CameraSettings& settings) {
  const std::string type = readString(camera, "type", place, "pinhole");
  if (type == "pinhole") {
    checkKeys(camera, place, {"type", "position", "yaw", "pitch", "focal_length", "near", "far"});
    PinholeCamera c;
    c.position = readVec3(camera, "position", place, c.position);
    c.yawDegrees = readNumber(camera, "yaw", place, 0);
    c.pitchDegrees = readNumber(camera, "pitch", place, 0);
    c.focalLengthPixels = readNumber(camera, "focal_length", place, height);
    c.nearPlane = readNumber(camera, "near", place, c.nearPlane);
    c.farPlane = readNumber(camera, "far", place, c.farPlane);
    if (!(c.focalLengthPixels > 0)) throw SceneError(placeOf(place, "focal_length"), "must be positive");
    if (!(c.nearPlane > 0 && c.farPlane > c.nearPlane)) throw SceneError(place, "needs 0 < near < far");
    settings.type = CameraSettings::Type::Pinhole;
    settings.pinhole = c;
    return cameraMatrices(c, width, height);
  }
  if (type == "look_at") {
    checkKeys(camera, place, {"type", "eye", "target", "up", "fov_y", "aspect", "near", "far"});
    LookAtCamera c;
    c.eye = readVec3(camera, "eye", place, c.eye);
    c.target = readVec3(camera, "target", place, c.target);
    c.up = readVec3(camera, "up", place, c.up);
    c.fovYDegrees = readNumber(camera, "fov_y", place, c.fovYDegrees);
    c.aspect = readNumber(camera, "aspect", place, 0);
    c.nearPlane = readNumber(camera, "near", place, c.nearPlane);
    c.farPlane = readNumber(camera, "far", place, c.farPlane);
    if (!(c.fovYDegrees > 0 && c.fovYDegrees < 180)) throw SceneError(placeOf(place, "fov_y"), "must be in (0, 180)");
    if (!(c.nearPlane > 0 && c.farPlane > c.nearPlane)) throw SceneError(place, "needs 0 < near < far");
    if (c.eye == c.target) throw SceneError(place, "eye and target are the same point");
    const glm::dvec3 forward(c.target[0] - c.eye[0], c.target[1] - c.eye[1], c.target[2] - c.eye[2]);
    const glm::dvec3 up(c.up[0], c.up[1], c.up[2]);
    if (!(glm::length(glm::cross(forward, up)) > 1e-9 * glm::length(forward) * glm::length(up))) {
      throw SceneError(placeOf(place, "up"), "is zero or parallel to the view direction (target - eye)");
    }
    settings.type = CameraSettings::Type::LookAt;
    settings.lookAt = c;
    return cameraMatrices(c, width, height);
  }
  if (type == "clip_space") {  // positions are clip coordinates (w = 1): exact control of window positions
    checkKeys(camera, place, {"type"});
    settings.type = CameraSettings::Type::ClipSpace;
    return {};
  }
  throw SceneError(placeOf(place, "type"), "'" + type + "' is not one of pinhole, look_at, clip_space");
}

// A draw's "blend" object (scenes/README.md): source, destination and op for colour and alpha
// alike, "colour" and "alpha" objects overriding them for one side, constants, write_mask and
// enable (default true; false keeps the write mask with blending off); or logic_op (a VkLogicOp
// name), which turns the logic op on and blending off (enable then defaults to false: Vulkan
// treats blending as disabled with a logic op).
softraster::BlendState readBlend(const json& b, const std::string& place) {
  using softraster::BlendFactor;
  using softraster::BlendOp;
  using softraster::LogicOp;
  checkKeys(b, place, {"enable", "source", "destination", "op", "colour", "alpha", "constants", "write_mask", "logic_op"});
  const std::vector<std::pair<const char*, BlendFactor>> factors = {
      {"zero", BlendFactor::Zero},
      {"one", BlendFactor::One},
      {"src_color", BlendFactor::SrcColor},
      {"one_minus_src_color", BlendFactor::OneMinusSrcColor},
      {"dst_color", BlendFactor::DstColor},
      {"one_minus_dst_color", BlendFactor::OneMinusDstColor},
      {"src_alpha", BlendFactor::SrcAlpha},
      {"one_minus_src_alpha", BlendFactor::OneMinusSrcAlpha},
      {"dst_alpha", BlendFactor::DstAlpha},
      {"one_minus_dst_alpha", BlendFactor::OneMinusDstAlpha},
      {"constant_color", BlendFactor::ConstantColor},
      {"one_minus_constant_color", BlendFactor::OneMinusConstantColor},
      {"constant_alpha", BlendFactor::ConstantAlpha},
      {"one_minus_constant_alpha", BlendFactor::OneMinusConstantAlpha},
      {"src_alpha_saturate", BlendFactor::SrcAlphaSaturate}};
  const std::vector<std::pair<const char*, BlendOp>> ops = {{"add", BlendOp::Add},
                                                            {"subtract", BlendOp::Subtract},
                                                            {"reverse_subtract", BlendOp::ReverseSubtract},
                                                            {"min", BlendOp::Min},
                                                            {"max", BlendOp::Max}};
  const std::vector<std::pair<const char*, LogicOp>> logicOps = {
      {"clear", LogicOp::Clear},       {"and", LogicOp::And},
      {"and_reverse", LogicOp::AndReverse}, {"copy", LogicOp::Copy},
      {"and_inverted", LogicOp::AndInverted}, {"no_op", LogicOp::NoOp},
      {"xor", LogicOp::Xor},           {"or", LogicOp::Or},
      {"nor", LogicOp::Nor},           {"equivalent", LogicOp::Equivalent},
      {"invert", LogicOp::Invert},     {"or_reverse", LogicOp::OrReverse},
      {"copy_inverted", LogicOp::CopyInverted}, {"or_inverted", LogicOp::OrInverted},
      {"nand", LogicOp::Nand},         {"set", LogicOp::Set}};
  softraster::BlendState state;
  state.logicOpEnable = b.contains("logic_op");
  if (state.logicOpEnable) state.logicOp = readEnum(b, "logic_op", place, LogicOp::Copy, logicOps);
  state.enable = readBool(b, "enable", place, !state.logicOpEnable);
  const BlendFactor source = readEnum(b, "source", place, BlendFactor::One, factors);
  const BlendFactor destination = readEnum(b, "destination", place, BlendFactor::Zero, factors);
  const BlendOp op = readEnum(b, "op", place, BlendOp::Add, ops);
  const auto side = [&](const char* key, BlendFactor& s, BlendFactor& dst, BlendOp& o) {
    s = source;
    dst = destination;
    o = op;
    if (!b.contains(key)) return;
    const std::string sp = placeOf(place, key);
    checkKeys(b[key], sp, {"source", "destination", "op"});
    s = readEnum(b[key], "source", sp, source, factors);
    dst = readEnum(b[key], "destination", sp, destination, factors);
    o = readEnum(b[key], "op", sp, op, ops);
  };
  side("colour", state.srcColorBlendFactor, state.dstColorBlendFactor, state.colorBlendOp);
  side("alpha", state.srcAlphaBlendFactor, state.dstAlphaBlendFactor, state.alphaBlendOp);
  if (b.contains("constants")) {
    const std::string cp = placeOf(place, "constants");
    const auto v = readNumbers(b["constants"], cp, 4, 4);
    for (int i = 0; i < 4; ++i) {
      if (!(v[static_cast<std::size_t>(i)] >= 0 && v[static_cast<std::size_t>(i)] <= 1)) {
        throw SceneError(placeOf(cp, std::to_string(i)), "must be in [0, 1]");
      }
      state.blendConstants[i] = static_cast<float>(v[static_cast<std::size_t>(i)]);
    }
  }
  if (b.contains("write_mask")) {
    const std::string mask = readString(b, "write_mask", place, "");
    state.colorWriteMask = 0;
    for (char c : mask) {
      const std::size_t bit = std::string_view("rgba").find(c);
      if (bit == std::string_view::npos || (state.colorWriteMask & (1u << bit))) {
        throw SceneError(placeOf(place, "write_mask"),
                         "'" + mask + "' is not a set of the letters r, g, b, a, each at most once (\"\" writes nothing)");
      }
      state.colorWriteMask = static_cast<std::uint8_t>(state.colorWriteMask | (1u << bit));
    }
  }
  return state;
}

const std::vector<std::pair<const char*, softraster::CompareOp>>& compareOps() {
  using softraster::CompareOp;
  static const std::vector<std::pair<const char*, CompareOp>> ops = {
      {"never", CompareOp::Never},     {"less", CompareOp::Less},         {"equal", CompareOp::Equal},
      {"less_or_equal", CompareOp::LessOrEqual}, {"greater", CompareOp::Greater}, {"not_equal", CompareOp::NotEqual},
      {"greater_or_equal", CompareOp::GreaterOrEqual}, {"always", CompareOp::Always}};
  return ops;
}

// A draw's "stencil" object (scenes/README.md): the op state for both faces, "front" and "back"
// objects overriding it for one face; "enable" (default true) turns the test on.
void readStencil(const json& s, const std::string& place, softraster::DepthState& depth) {
  using softraster::StencilOp;
  checkKeys(s, place, {"enable", "fail_op", "pass_op", "depth_fail_op", "compare_op", "compare_mask", "write_mask",
                       "reference", "front", "back"});
  const std::vector<std::pair<const char*, StencilOp>> ops = {
      {"keep", StencilOp::Keep},
      {"zero", StencilOp::Zero},
      {"replace", StencilOp::Replace},
      {"increment_and_clamp", StencilOp::IncrementAndClamp},
      {"decrement_and_clamp", StencilOp::DecrementAndClamp},
      {"invert", StencilOp::Invert},
      {"increment_and_wrap", StencilOp::IncrementAndWrap},
      {"decrement_and_wrap", StencilOp::DecrementAndWrap}};
  const auto face = [&](const json& f, const std::string& at, softraster::StencilOpState fallback) {
    softraster::StencilOpState out;
    out.failOp = readEnum(f, "fail_op", at, fallback.failOp, ops);
    out.passOp = readEnum(f, "pass_op", at, fallback.passOp, ops);
    out.depthFailOp = readEnum(f, "depth_fail_op", at, fallback.depthFailOp, ops);
    out.compareOp = readEnum(f, "compare_op", at, fallback.compareOp, compareOps());
    // The stencil aspect has 8 bits: Vulkan uses only the low 8 bits of each value.
    out.compareMask = static_cast<std::uint32_t>(readCount(f, "compare_mask", at, fallback.compareMask, 255));
    out.writeMask = static_cast<std::uint32_t>(readCount(f, "write_mask", at, fallback.writeMask, 255));
    out.reference = static_cast<std::uint32_t>(readCount(f, "reference", at, fallback.reference, 255));
    return out;
  };
  depth.stencilTestEnable = readBool(s, "enable", place, true);
  const softraster::StencilOpState both = face(s, place, {});
  for (const char* side : {"front", "back"}) {
    softraster::StencilOpState& out = std::string_view(side) == "front" ? depth.front : depth.back;
    out = both;
    if (!s.contains(side)) continue;
    const std::string at = placeOf(place, side);
    checkKeys(s[side], at, {"fail_op", "pass_op", "depth_fail_op", "compare_op", "compare_mask", "write_mask", "reference"});
    out = face(s[side], at, both);
  }
}

void readDrawState(const json& d, const std::string& place, softraster::PipelineState& state) {
  using softraster::CompareOp;
  using softraster::CullMode;
  using softraster::FrontFace;
  using softraster::Topology;
  state.topology = readEnum(d, "topology", place, state.topology,
                            {{"point_list", Topology::PointList}, {"line_list", Topology::LineList},
                             {"line_strip", Topology::LineStrip}, {"triangle_list", Topology::TriangleList},
                             {"triangle_strip", Topology::TriangleStrip}, {"triangle_fan", Topology::TriangleFan},
                             {"line_list_with_adjacency", Topology::LineListWithAdjacency},
                             {"line_strip_with_adjacency", Topology::LineStripWithAdjacency},
                             {"triangle_list_with_adjacency", Topology::TriangleListWithAdjacency},
                             {"triangle_strip_with_adjacency", Topology::TriangleStripWithAdjacency}});
  state.primitiveRestartEnable = readBool(d, "primitive_restart", place, state.primitiveRestartEnable);
  const auto stripOrFan = [](Topology t) {
    return t == Topology::LineStrip || t == Topology::TriangleStrip || t == Topology::TriangleFan ||
           t == Topology::LineStripWithAdjacency || t == Topology::TriangleStripWithAdjacency;
  };
  if (state.primitiveRestartEnable && !stripOrFan(state.topology)) {
    throw SceneError(placeOf(place, "primitive_restart"),
                     "needs a strip or fan topology (VUID-VkPipelineInputAssemblyStateCreateInfo-topology-06252: "
                     "\"If the primitiveTopologyListRestart feature is not enabled, and topology is "
                     "VK_PRIMITIVE_TOPOLOGY_POINT_LIST, VK_PRIMITIVE_TOPOLOGY_LINE_LIST, "
                     "VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST, VK_PRIMITIVE_TOPOLOGY_LINE_LIST_WITH_ADJACENCY, or "
                     "VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST_WITH_ADJACENCY, primitiveRestartEnable must be VK_FALSE\"; "
                     "vkref does not enable that feature)");
  }
  if (d.contains("viewport")) {
    const std::string vp = placeOf(place, "viewport");
    const json& v = d["viewport"];
    checkKeys(v, vp, {"x", "y", "width", "height", "min_depth", "max_depth"});
    auto& viewport = state.viewport;
    viewport.x = readFloat(v, "x", vp, 0);
    viewport.y = readFloat(v, "y", vp, 0);
    viewport.width = readFloat(v, "width", vp, 0);
    viewport.height = readFloat(v, "height", vp, 0);
    viewport.minDepth = readFloat(v, "min_depth", vp, 0);
    viewport.maxDepth = readFloat(v, "max_depth", vp, 1);
    checkViewport(viewport, vp);
  }
  if (d.contains("scissor")) {
    const std::string sp = placeOf(place, "scissor");
    const json& sc = d["scissor"];
    checkKeys(sc, sp, {"x", "y", "width", "height"});
    constexpr std::uint64_t kIntMax = std::numeric_limits<std::int32_t>::max();
    const std::uint64_t x = readCount(sc, "x", sp, 0, kIntMax), y = readCount(sc, "y", sp, 0, kIntMax);
    const std::uint64_t width = readCount(sc, "width", sp, 0, std::numeric_limits<std::uint32_t>::max());
    const std::uint64_t height = readCount(sc, "height", sp, 0, std::numeric_limits<std::uint32_t>::max());
    if (x + width > kIntMax || y + height > kIntMax) {
      throw SceneError(sp, "x + width and y + height must fit in a 32-bit signed integer (Vulkan: "
                           "\"evaluation of (offset.x + extent.width) must not cause a signed integer addition "
                           "overflow\")");
    }
    state.scissor = {static_cast<std::int32_t>(x), static_cast<std::int32_t>(y), static_cast<std::uint32_t>(width),
                     static_cast<std::uint32_t>(height)};
  }
  auto& rs = state.rasterization;
  rs.depthClampEnable = readBool(d, "depth_clamp", place, rs.depthClampEnable);
  rs.polygonMode = readEnum(d, "polygon_mode", place, rs.polygonMode,
                            {{"fill", softraster::PolygonMode::Fill}, {"line", softraster::PolygonMode::Line},
                             {"point", softraster::PolygonMode::Point}});
  rs.lineWidth = readFloat(d, "line_width", place, rs.lineWidth);
  if (!(rs.lineWidth >= Limits::kMinLineWidth && rs.lineWidth <= Limits::kMaxLineWidth)) {
    throw SceneError(placeOf(place, "line_width"), "must be in [1, 255], the device's lineWidthRange (Vulkan: "
                                                   "\"lineWidth must be within the range lineWidthRange\")");
  }
  rs.lineRasterization = readEnum(d, "line_rasterization", place, rs.lineRasterization,
                                  {{"rectangular", softraster::LineRasterization::Rectangular},
                                   {"bresenham", softraster::LineRasterization::Bresenham}});
  rs.provokingVertex = readEnum(d, "provoking_vertex", place, rs.provokingVertex,
                                {{"first", softraster::ProvokingVertex::First}, {"last", softraster::ProvokingVertex::Last}});
  if (d.contains("line_stipple")) {
    const std::string sp = placeOf(place, "line_stipple");
    const json& st = d["line_stipple"];
    checkKeys(st, sp, {"factor", "pattern"});
    if (!st.contains("factor") || !st.contains("pattern")) throw SceneError(sp, "needs \"factor\" and \"pattern\"");
    const std::uint64_t factor = readCount(st, "factor", sp, 1);
    if (factor < 1 || factor > 256) {
      throw SceneError(placeOf(sp, "factor"), "must be in [1, 256] (VUID-VkGraphicsPipelineCreateInfo-stippledLineEnable-"
                                              "02767: \"lineStippleFactor ... must be in the range [1,256]\")");
    }
    rs.lineStipple.enable = true;
    rs.lineStipple.factor = static_cast<std::uint32_t>(factor);
    rs.lineStipple.pattern = static_cast<std::uint16_t>(readCount(st, "pattern", sp, 0xFFFF, 0xFFFF));
  }
  if (d.contains("depth_bias")) {
    const std::string bp = placeOf(place, "depth_bias");
    const json& b = d["depth_bias"];
    checkKeys(b, bp, {"constant", "slope", "clamp"});
    rs.depthBias.enable = true;
    rs.depthBias.constantFactor = readFloat(b, "constant", bp, 0);
    rs.depthBias.slopeFactor = readFloat(b, "slope", bp, 0);
    rs.depthBias.clamp = readFloat(b, "clamp", bp, 0);
  }
  rs.cullMode = readEnum(d, "cull", place, rs.cullMode,
                         {{"none", CullMode::None}, {"front", CullMode::Front}, {"back", CullMode::Back},
                          {"front_and_back", CullMode::FrontAndBack}});
  rs.frontFace = readEnum(d, "front_face", place, rs.frontFace,
                          {{"counter_clockwise", FrontFace::CounterClockwise}, {"clockwise", FrontFace::Clockwise}});
  if (d.contains("blend")) state.blend = readBlend(d["blend"], placeOf(place, "blend"));
  // Colour attachments 1..: each one's own blend; the constants and logic op are "blend"'s.
  if (d.contains("more_blend")) {
    const std::string mp = placeOf(place, "more_blend");
    const json& more = d["more_blend"];
    if (!more.is_array() || more.size() > state.moreBlend.size()) {
      throw SceneError(mp, "expected an array of at most " + std::to_string(state.moreBlend.size()) +
                               " blend objects (colour attachments 1..)");
    }
    for (std::size_t a = 0; a < more.size(); ++a) {
      const std::string ap = placeOf(mp, std::to_string(a));
      for (const char* shared : {"constants", "logic_op"}) {
        if (more[a].is_object() && more[a].contains(shared)) {
          throw SceneError(placeOf(ap, shared), "is the pipeline's, for every colour attachment: give it in \"blend\"");
        }
      }
      state.moreBlend[a] = readBlend(more[a], ap);
    }
  }
  auto& ds = state.depth;
  ds.testEnable = readBool(d, "depth_test", place, ds.testEnable);
  ds.writeEnable = readBool(d, "depth_write", place, ds.writeEnable);
  ds.compareOp = readEnum(d, "depth_compare", place, ds.compareOp, compareOps());
  if (readBool(d, "depth_bounds_test", place, false)) {
    throw SceneError(placeOf(place, "depth_bounds_test"),
                     "lavapipe does not offer the depthBounds feature, and Vulkan says \"If the depthBounds feature is "
                     "not enabled, depthBoundsTestEnable must be VK_FALSE\" "
                     "(VUID-VkPipelineDepthStencilStateCreateInfo-depthBoundsTestEnable-00598)");
  }
  if (d.contains("stencil")) readStencil(d["stencil"], placeOf(place, "stencil"), ds);
  if (d.contains("multisample")) {
    const std::string mp = placeOf(place, "multisample");
    const json& m = d["multisample"];
    checkKeys(m, mp, {"sample_mask", "alpha_to_coverage", "alpha_to_one", "min_sample_shading"});
    auto& ms = state.multisample;
    ms.sampleMask = static_cast<std::uint32_t>(readCount(m, "sample_mask", mp, ms.sampleMask, 0xFFFFFFFFu));
    ms.alphaToCoverageEnable = readBool(m, "alpha_to_coverage", mp, ms.alphaToCoverageEnable);
    ms.alphaToOneEnable = readBool(m, "alpha_to_one", mp, ms.alphaToOneEnable);
    if (m.contains("min_sample_shading")) {
      ms.sampleShadingEnable = true;
      ms.minSampleShading = readFloat(m, "min_sample_shading", mp, 0.0f);
      if (!(ms.minSampleShading >= 0.0f && ms.minSampleShading <= 1.0f)) {
        throw SceneError(placeOf(mp, "min_sample_shading"),
                         "must be in [0, 1] (VUID-VkPipelineMultisampleStateCreateInfo-minSampleShading-00786: "
                         "\"If sampleShadingEnable is VK_TRUE, minSampleShading must be in the range [0,1]\")");
      }
    }
    if ((ms.alphaToCoverageEnable || ms.alphaToOneEnable || ms.sampleShadingEnable) &&
        rs.lineRasterization == softraster::LineRasterization::Bresenham) {
      throw SceneError(mp, "alpha to coverage, alpha to one and sample shading need rectangular lines "
                           "(VUID-VkGraphicsPipelineCreateInfo-lineRasterizationMode-02766: \"If the lineRasterizationMode "
                           "member of a VkPipelineRasterizationLineStateCreateInfoEXT structure included in the pNext chain "
                           "of pRasterizationState is VK_LINE_RASTERIZATION_MODE_BRESENHAM_EXT or "
                           "VK_LINE_RASTERIZATION_MODE_RECTANGULAR_SMOOTH_EXT, then the alphaToCoverageEnable, "
                           "alphaToOneEnable, and sampleShadingEnable members of pMultisampleState must all be VK_FALSE\")");
    }
  }
}

// Limits of a procedural sphere ("sphere": {...}): enough for the bench's 1M triangles, small
// enough that a typo cannot ask for gigabytes.
constexpr std::int64_t kMaxSphereDivisions = 10000;
constexpr std::int64_t kMaxSphereTriangles = 10'000'000;

std::int64_t readSphereDivisions(const json& sphere, const char* key, const std::string& place) {
  const std::string at = placeOf(place, key);
  if (!sphere.contains(key)) throw SceneError(at, "missing (an integer, 3.." + std::to_string(kMaxSphereDivisions) + ")");
  const json& v = sphere[key];
  if (!v.is_number_integer()) throw SceneError(at, "expected an integer");
  const std::int64_t n = v.is_number_unsigned() && v.get<std::uint64_t>() > std::uint64_t{INT64_MAX}
                             ? std::numeric_limits<std::int64_t>::max()
                             : v.get<std::int64_t>();
  if (n < 3) throw SceneError(at, "must be at least 3");
  if (n > kMaxSphereDivisions) throw SceneError(at, "must be at most " + std::to_string(kMaxSphereDivisions));
  return n;
}

// A UV sphere: `segments` around its axis (y), `rings` from pole to pole (a single vertex at
// each pole), 2 * segments * (rings - 1) triangles, indexed, every face wound so that its
// normal by the right-hand rule points outwards (front facing with counter_clockwise, as
// meshes/sphere.obj). Each vertex is coloured by its normal, 0.5 + 0.5 * n, alpha 1 (unless the
// draw gives a "colour"), and has its exact normal. Positions
// are computed in double and rounded to float once, so both renderers get the same bits.
void makeSphere(const json& sphere, const std::string& place, Draw& draw) {
  checkKeys(sphere, place, {"segments", "rings", "radius", "centre"});
  const std::int64_t segments = readSphereDivisions(sphere, "segments", place);
  const std::int64_t rings = readSphereDivisions(sphere, "rings", place);
  if (2 * segments * (rings - 1) > kMaxSphereTriangles) {
    throw SceneError(place, "2 * segments * (rings - 1) = " + std::to_string(2 * segments * (rings - 1)) +
                                " triangles, more than " + std::to_string(kMaxSphereTriangles));
  }
  const double radius = readNumber(sphere, "radius", place, 1.0);
  if (!(radius > 0) || !std::isfinite(radius)) throw SceneError(placeOf(place, "radius"), "must be a positive number");
  const std::array<double, 3> centre = readVec3(sphere, "centre", place, {0, 0, 0});
  constexpr double kPi = 3.14159265358979323846;

  std::vector<std::array<double, 3>> normals;
  normals.reserve(static_cast<std::size_t>(segments * (rings - 1) + 2));
  normals.push_back({0, -1, 0});
  for (std::int64_t j = 1; j < rings; ++j) {
    const double phi = kPi * static_cast<double>(j) / static_cast<double>(rings);
    for (std::int64_t i = 0; i < segments; ++i) {
      const double theta = 2 * kPi * static_cast<double>(i) / static_cast<double>(segments);
      normals.push_back({std::sin(phi) * std::cos(theta), -std::cos(phi), std::sin(phi) * std::sin(theta)});
    }
  }
  normals.push_back({0, 1, 0});
  for (const auto& n : normals) {
    draw.mesh.positions.push_back({static_cast<float>(centre[0] + radius * n[0]),
                                   static_cast<float>(centre[1] + radius * n[1]),
                                   static_cast<float>(centre[2] + radius * n[2])});
    draw.mesh.colours.push_back({static_cast<float>(0.5 + 0.5 * n[0]), static_cast<float>(0.5 + 0.5 * n[1]),
                                 static_cast<float>(0.5 + 0.5 * n[2]), 1.0f});
    draw.mesh.normals.push_back({static_cast<float>(n[0]), static_cast<float>(n[1]), static_cast<float>(n[2])});
  }
  const auto top = std::uint32_t{0}, bottom = static_cast<std::uint32_t>(normals.size() - 1);
  const auto ring = [&](std::int64_t j, std::int64_t i) {  // ring j in 1..rings-1, segment i (wrapping)
    return static_cast<std::uint32_t>(1 + (j - 1) * segments + i % segments);
  };
  // Appends the triangle wound outwards: (b - a) x (c - a) points away from the centre.
  const auto outward = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const auto& p = normals[a];
    const auto& q = normals[b];
    const auto& r = normals[c];
    const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, v[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double m[3] = {p[0] + q[0] + r[0], p[1] + q[1] + r[1], p[2] + q[2] + r[2]};
    const bool out = n[0] * m[0] + n[1] * m[1] + n[2] * m[2] > 0;
    draw.indices.insert(draw.indices.end(), {a, out ? b : c, out ? c : b});
  };
  draw.indices.reserve(static_cast<std::size_t>(6 * segments * (rings - 1)));
  for (std::int64_t i = 0; i < segments; ++i) {
    outward(top, ring(1, i), ring(1, i + 1));
    outward(bottom, ring(rings - 1, i + 1), ring(rings - 1, i));
  }
  for (std::int64_t j = 1; j + 1 < rings; ++j) {
    for (std::int64_t i = 0; i < segments; ++i) {
      outward(ring(j, i), ring(j + 1, i), ring(j + 1, i + 1));
      outward(ring(j, i), ring(j + 1, i + 1), ring(j, i + 1));
    }
  }
}

Draw readDrawMesh(const json& d, const std::string& place, const std::filesystem::path& sceneDir, ColourRange range);

// "transform": the object-to-world matrix M = T * Rz * Ry * Rx * S (scale first, then rotations
// about x, y and z, then translation; angles in degrees, right-handed about the scene's axes,
// "rotate" plus "spin" times the scene's time).
glm::dmat4 readTransform(const json& t, const std::string& place, double time, bool& spins) {
  checkKeys(t, place, {"scale", "rotate", "spin", "translate"});
  glm::dvec3 scale(1.0);
  if (t.contains("scale")) {
    if (t["scale"].is_number()) {
      scale = glm::dvec3(readNumber(t["scale"], placeOf(place, "scale")));
    } else {
      const auto v = readNumbers(t["scale"], placeOf(place, "scale"), 3, 3);
      scale = {v[0], v[1], v[2]};
    }
  }
  const auto rotate = readVec3(t, "rotate", place, {0, 0, 0});
  const auto spin = readVec3(t, "spin", place, {0, 0, 0});
  const auto translate = readVec3(t, "translate", place, {0, 0, 0});
  for (double v : {scale.x, scale.y, scale.z, rotate[0], rotate[1], rotate[2], spin[0], spin[1], spin[2], translate[0],
                   translate[1], translate[2]}) {
    if (!std::isfinite(v)) throw SceneError(place, "every value must be finite");
  }
  spins = spin[0] != 0 || spin[1] != 0 || spin[2] != 0;
  glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(translate[0], translate[1], translate[2]));
  const glm::dvec3 axes[3] = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}};
  for (int k = 0; k < 3; ++k) {  // z, then y, then x: applied to a point in the order x, y, z
    const int a = 2 - k;
    m = glm::rotate(m, glm::radians(rotate[a] + spin[a] * time), axes[k]);
  }
  return glm::scale(m, scale);
}

// "material": what the lit models read beyond the vertex colours.
shaders::Material readMaterial(const json& m, const std::string& place) {
  checkKeys(m, place, {"indirect", "ambient", "specular", "shininess"});
  shaders::Material material;
  const auto rgb = [&](const char* key, softraster::Vec4 fallback) {
    if (!m.contains(key)) return fallback;
    const auto v = readNumbers(m[key], placeOf(place, key), 3, 3);
    for (double c : v) {
      if (!(c >= 0) || !std::isfinite(c)) throw SceneError(placeOf(place, key), "components must be finite and >= 0");
    }
    return softraster::Vec4{static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), 0};
  };
  material.indirect = rgb("indirect", material.indirect);
  material.ambient = rgb("ambient", material.ambient);
  material.specular = rgb("specular", material.specular);
  material.shininess = static_cast<float>(readNumber(m, "shininess", place, material.shininess));
  if (!(material.shininess >= 0 && material.shininess <= 10000)) {
    throw SceneError(placeOf(place, "shininess"), "must be in [0, 10000]");
  }
  return material;
}

// Normals for a model that reads them: "normals" is "flat", "smooth", "file" (the OBJ's vn) or,
// for inline positions, one [x, y, z] per position. Default: the OBJ's vn when it has them, the
// sphere's own, else flat.
void readNormals(const json& d, const std::string& place, Draw& draw, bool haveOwn) {
  const std::string at = placeOf(place, "normals");
  std::string mode = haveOwn ? "file" : "flat";
  if (d.contains("normals")) {
    const json& n = d["normals"];
    if (n.is_array()) {
      if (!d.contains("positions")) throw SceneError(at, "inline normals need inline positions");
      if (n.size() != draw.mesh.vertexCount()) {
        throw SceneError(at, "expected one normal per position (" + std::to_string(draw.mesh.vertexCount()) + ")");
      }
      draw.mesh.normals.clear();
      for (std::size_t i = 0; i < n.size(); ++i) {
        const auto v = readNumbers(n[i], placeOf(at, std::to_string(i)), 3, 3);
        draw.mesh.normals.push_back({static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])});
      }
      return;
    }
    mode = readString(d, "normals", place, mode);
  }
  if (mode == "file") {
    if (!haveOwn) throw SceneError(at, "'file': the mesh has no normals of its own (an OBJ without vn)");
    return;
  }
  if (mode != "flat" && mode != "smooth") throw SceneError(at, "'" + mode + "' is not one of flat, smooth, file, or an array");
  if (draw.state.topology != softraster::Topology::TriangleList) {
    throw SceneError(at, "flat and smooth normals are computed for triangle lists only; give one per position");
  }
  computeNormals(draw.mesh, draw.indices, draw.indexed, mode == "flat" ? NormalMode::Flat : NormalMode::Smooth);
}

// Textures loaded by this scene, by file, format and mip choice, so draws share them.
using TextureCache = std::map<std::tuple<std::filesystem::path, softraster::TextureFormat, bool>,
                              std::shared_ptr<const softraster::Texture>>;

// "texture": {"file", "format", "mipmaps", the sampler's fields}, as Draw::Texture.
Draw::Texture readTexture(const json& t, const std::string& place, const std::filesystem::path& sceneDir,
                          TextureCache& cache) {
  using namespace softraster;
  if (!t.is_object()) throw SceneError(place, "expected an object with \"file\" and the sampler's fields");
  checkKeys(t, place, {"file", "format", "mipmaps", "mag_filter", "min_filter", "mipmap_mode", "address_mode",
                       "address_mode_u", "address_mode_v", "mip_lod_bias", "min_lod", "max_lod", "border_colour"});
  if (!t.contains("file")) throw SceneError(place, "needs \"file\" (a PNG, relative to the scene file)");
  const std::filesystem::path file = sceneDir / readString(t, "file", place, "");
  const TextureFormat format = readEnum(t, "format", place, TextureFormat::R8G8B8A8Unorm,
                                        {{"unorm", TextureFormat::R8G8B8A8Unorm}, {"srgb", TextureFormat::R8G8B8A8Srgb}});
  const bool mipmaps = readBool(t, "mipmaps", place, false);
  Draw::Texture out;
  auto& cached = cache[{file, format, mipmaps}];
  if (!cached) {
    auto loaded = loadTexture(file, format, mipmaps);
    if (!loaded) throw SceneError(placeOf(place, "file"), loaded.error());
    cached = std::make_shared<const softraster::Texture>(std::move(*loaded));
  }
  out.texture = cached;
  const std::vector<std::pair<const char*, Filter>> filters{{"nearest", Filter::Nearest}, {"linear", Filter::Linear}};
  const std::vector<std::pair<const char*, AddressMode>> modes{{"repeat", AddressMode::Repeat},
                                                               {"mirrored_repeat", AddressMode::MirroredRepeat},
                                                               {"clamp_to_edge", AddressMode::ClampToEdge},
                                                               {"clamp_to_border", AddressMode::ClampToBorder}};
  SamplerState& s = out.sampler;
  s.magFilter = readEnum(t, "mag_filter", place, s.magFilter, filters);
  s.minFilter = readEnum(t, "min_filter", place, s.minFilter, filters);
  s.mipmapMode = readEnum(t, "mipmap_mode", place, s.mipmapMode,
                          {{"nearest", MipmapMode::Nearest}, {"linear", MipmapMode::Linear}});
  if (t.contains("address_mode") && (t.contains("address_mode_u") || t.contains("address_mode_v"))) {
    throw SceneError(place, "give \"address_mode\" (both directions) or \"address_mode_u\"/\"address_mode_v\", not both");
  }
  s.addressModeU = s.addressModeV = readEnum(t, "address_mode", place, s.addressModeU, modes);
  s.addressModeU = readEnum(t, "address_mode_u", place, s.addressModeU, modes);
  s.addressModeV = readEnum(t, "address_mode_v", place, s.addressModeV, modes);
  s.mipLodBias = readFloat(t, "mip_lod_bias", place, s.mipLodBias);
  s.minLod = readFloat(t, "min_lod", place, s.minLod);
  s.maxLod = readFloat(t, "max_lod", place, s.maxLod);
  s.borderColor = readEnum(t, "border_colour", place, s.borderColor,
                           {{"transparent_black", BorderColor::TransparentBlack},
                            {"opaque_black", BorderColor::OpaqueBlack},
                            {"opaque_white", BorderColor::OpaqueWhite}});
  if (const softraster::Status valid = softraster::Sampler2D{out.texture.get(), s}.validate(); !valid) {
    throw SceneError(place, valid.message());
  }
  return out;
}

// "shadow_map": {"pass", "compare", "address_mode", "border_colour", "bias"}: the depth pass
// (by name, among `passNames`) a shadowed model samples, and its sampler. Nearest filtering
// only: lavapipe gives depth formats no SAMPLED_IMAGE_FILTER_LINEAR (Vulkan then forbids linear).
Draw::Texture readShadowMap(const json& t, const std::string& place, const std::vector<std::string>& passNames,
                            shaders::ShadowMapSampler kind, float& bias) {
  using namespace softraster;
  if (!t.is_object()) throw SceneError(place, "expected an object with \"pass\" and the sampler's fields");
  checkKeys(t, place, {"pass", "compare", "address_mode", "border_colour", "bias"});
  if (!t.contains("pass")) throw SceneError(place, "needs \"pass\" (the name of a depth pass in \"passes\")");
  const std::string pass = readString(t, "pass", place, "");
  Draw::Texture out;
  const auto found = std::find(passNames.begin(), passNames.end(), pass);
  if (found == passNames.end()) {
    std::string list;
    for (const std::string& n : passNames) list += (list.empty() ? "" : ", ") + n;
    throw SceneError(placeOf(place, "pass"), "no depth pass is called '" + pass + "'" +
                                                 (list.empty() ? " (the scene has no \"passes\")" : " (passes: " + list + ")"));
  }
  out.pass = static_cast<int>(found - passNames.begin());
  SamplerState& s = out.sampler;
  s.magFilter = s.minFilter = Filter::Nearest;
  s.maxLod = 0.0f;  // one level
  s.addressModeU = s.addressModeV = readEnum(t, "address_mode", place, AddressMode::ClampToEdge,
                                             {{"repeat", AddressMode::Repeat},
                                              {"mirrored_repeat", AddressMode::MirroredRepeat},
                                              {"clamp_to_edge", AddressMode::ClampToEdge},
                                              {"clamp_to_border", AddressMode::ClampToBorder}});
  s.borderColor = readEnum(t, "border_colour", place, BorderColor::OpaqueWhite,
                           {{"transparent_black", BorderColor::TransparentBlack},
                            {"opaque_black", BorderColor::OpaqueBlack},
                            {"opaque_white", BorderColor::OpaqueWhite}});
  if (kind == shaders::ShadowMapSampler::Comparison) {
    s.compareEnable = true;
    s.compareOp = readEnum(t, "compare", place, CompareOp::LessOrEqual,
                           {{"never", CompareOp::Never}, {"less", CompareOp::Less}, {"equal", CompareOp::Equal},
                            {"less_or_equal", CompareOp::LessOrEqual}, {"greater", CompareOp::Greater},
                            {"not_equal", CompareOp::NotEqual}, {"greater_or_equal", CompareOp::GreaterOrEqual},
                            {"always", CompareOp::Always}});
  } else if (t.contains("compare")) {
    throw SceneError(placeOf(place, "compare"), "this model compares in its shader (reference <= depth): the sampler has no compare op");
  }
  bias = readFloat(t, "bias", place, 0.0f);
  return out;
}

// Texture coordinates for a model that reads them: the OBJ's vt, or "texcoords" (one [u, v] per
// inline position).
void readTexcoords(const json& d, const std::string& place, Draw& draw, bool haveOwn) {
  const std::string at = placeOf(place, "texcoords");
  if (d.contains("texcoords")) {
    const json& t = d["texcoords"];
    if (!d.contains("positions")) throw SceneError(at, "inline texture coordinates need inline positions");
    if (!t.is_array() || t.size() != draw.mesh.vertexCount()) {
      throw SceneError(at, "expected one [u, v] per position (" + std::to_string(draw.mesh.vertexCount()) + ")");
    }
    draw.mesh.texcoords.clear();
    for (std::size_t i = 0; i < t.size(); ++i) {
      const auto v = readNumbers(t[i], placeOf(at, std::to_string(i)), 2, 2);
      const softraster::Vec2 uv{static_cast<float>(v[0]), static_cast<float>(v[1])};
      if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) throw SceneError(placeOf(at, std::to_string(i)), "must be finite in float");
      draw.mesh.texcoords.push_back(uv);
    }
    return;
  }
  if (!haveOwn) {
    throw SceneError(place, "shading '" + std::string(draw.shading->name) +
                                "' reads texture coordinates: give \"texcoords\" or an OBJ whose every face corner has a vt");
  }
}

Draw readDraw(const json& d, const std::string& place, const std::filesystem::path& sceneDir, double time,
              TextureCache& textures, const std::vector<std::string>& passNames, ColourRange range) {
  Draw draw = readDrawMesh(d, place, sceneDir, range);
  if (draw.shading->depthPassOnly) {
    throw SceneError(placeOf(place, "shading"), "'" + std::string(draw.shading->name) +
                                                    "' writes no colour: it is the model of depth passes (\"passes\"), not of a draw");
  }
  if (d.contains("transform")) draw.model = readTransform(d["transform"], placeOf(place, "transform"), time, draw.spins);
  if (d.contains("material")) draw.material = readMaterial(d["material"], placeOf(place, "material"));
  if ((draw.shading->meshInputs & shaders::kReadsTexcoords) != 0) {  // before normals: flat ones rewrite the mesh
    readTexcoords(d, place, draw, !draw.mesh.texcoords.empty());
  } else {
    if (d.contains("texcoords")) {
      throw SceneError(placeOf(place, "texcoords"), "shading '" + std::string(draw.shading->name) + "' reads no texture coordinates");
    }
    draw.mesh.texcoords.clear();
  }
  const bool readsNormals = (draw.shading->meshInputs & shaders::kReadsNormals) != 0;
  if (readsNormals) {
    readNormals(d, place, draw, !draw.mesh.normals.empty());
  } else {
    if (d.contains("normals")) throw SceneError(placeOf(place, "normals"), "shading '" + std::string(draw.shading->name) + "' reads no normals");
    draw.mesh.normals.clear();
  }
  if ((draw.shading->meshInputs & shaders::kReadsTangents) != 0) {
    if (draw.state.topology != softraster::Topology::TriangleList) {
      throw SceneError(placeOf(place, "topology"), "tangents are computed for triangle lists only");
    }
    computeTangents(draw.mesh, draw.indices, draw.indexed);
  }
  if (draw.shading->shadowMap != shaders::ShadowMapSampler::None) {
    if (!d.contains("shadow_map")) {
      throw SceneError(place, "shading '" + std::string(draw.shading->name) +
                                  "' samples a shadow map: give \"shadow_map\" (a depth pass's name and the sampler)");
    }
    if (d.contains("texture")) throw SceneError(placeOf(place, "texture"), "shading '" + std::string(draw.shading->name) + "' samples no texture");
    draw.textures.push_back(readShadowMap(d["shadow_map"], placeOf(place, "shadow_map"), passNames,
                                          draw.shading->shadowMap, draw.shadowBias));
  } else if (d.contains("shadow_map")) {
    throw SceneError(placeOf(place, "shadow_map"), "shading '" + std::string(draw.shading->name) + "' samples no shadow map");
  } else if (draw.shading->textures > 0) {
    if (!d.contains("texture")) {
      throw SceneError(place, "shading '" + std::string(draw.shading->name) + "' samples a texture: give \"texture\"");
    }
    draw.textures.push_back(readTexture(d["texture"], placeOf(place, "texture"), sceneDir, textures));
  } else if (d.contains("texture")) {
    throw SceneError(placeOf(place, "texture"), "shading '" + std::string(draw.shading->name) + "' samples no texture");
  }
  if (draw.shading->textures > 1) {
    if (!d.contains("normal_map")) {
      throw SceneError(place, "shading '" + std::string(draw.shading->name) + "' samples a normal map: give \"normal_map\"");
    }
    draw.textures.push_back(readTexture(d["normal_map"], placeOf(place, "normal_map"), sceneDir, textures));
  } else if (d.contains("normal_map")) {
    throw SceneError(placeOf(place, "normal_map"), "shading '" + std::string(draw.shading->name) + "' samples no normal map");
  }
  return draw;
}

Draw readDrawMesh(const json& d, const std::string& place, const std::filesystem::path& sceneDir, ColourRange range) {
  checkKeys(d, place, {"name", "obj", "sphere", "positions", "colours", "colour", "indices", "normals", "texcoords",
                       "texture", "normal_map", "shadow_map", "shading",
                       "transform", "material", "topology", "viewport", "scissor", "cull", "front_face", "depth_clamp",
                       "depth_bias", "line_width", "line_rasterization", "point_size", "polygon_mode", "blend",
                       "more_blend", "depth_test", "depth_write", "depth_compare", "depth_bounds_test", "stencil",
                       "primitive_restart", "provoking_vertex", "line_stipple", "multisample"});
  Draw draw;
  draw.name = readString(d, "name", place, place);
  draw.shading = readShadingModel(d, place);
  readDrawState(d, place, draw.state);
  draw.pointSize = readFloat(d, "point_size", place, draw.pointSize);
  if (!(draw.pointSize > Limits::kMinPointSize && draw.pointSize <= Limits::kMaxPointSize)) {
    throw SceneError(placeOf(place, "point_size"), "must be in (0, 255], the device's pointSizeRange (Vulkan clamps "
                                                   "gl_PointSize to it, so a larger size would not draw what it says)");
  }
  const softraster::Vec4 colour = d.contains("colour") ? readColour(d["colour"], placeOf(place, "colour"), range)
                                                       : softraster::Vec4{1, 1, 1, 1};

  if (d.contains("sphere")) {
    for (const char* other : {"obj", "positions", "indices", "colours"}) {
      if (d.contains(other)) {
        throw SceneError(place, std::string("a draw has either \"sphere\" or \"") + other + "\", not both");
      }
    }
    if (draw.state.topology != softraster::Topology::TriangleList) {
      throw SceneError(placeOf(place, "topology"), "a sphere is a triangle list");
    }
    makeSphere(d["sphere"], placeOf(place, "sphere"), draw);
    if (d.contains("colour")) draw.mesh.colours.assign(draw.mesh.vertexCount(), colour);
    return draw;
  }

  if (d.contains("obj")) {
    if (d.contains("positions") || d.contains("indices") || d.contains("colours")) {
      throw SceneError(place, "a draw has either \"obj\" or inline \"positions\"/\"indices\", not both");
    }
    if (draw.state.topology != softraster::Topology::TriangleList) {  // an OBJ mesh has faces
      throw SceneError(placeOf(place, "topology"), "an OBJ mesh is a triangle list");
    }
    const std::string file = readString(d, "obj", place, "");
    auto mesh = loadObjMesh(sceneDir / file, colour);
    if (!mesh) throw SceneError(placeOf(place, "obj"), mesh.error());
    draw.mesh = std::move(mesh->vertices);
    draw.indices = std::move(mesh->indices);
    return draw;
  }

  if (!d.contains("positions")) throw SceneError(place, "a draw needs \"obj\", \"sphere\" or \"positions\"");
  const json& positions = d["positions"];
  if (!positions.is_array() || positions.empty()) throw SceneError(placeOf(place, "positions"), "expected an array of [x, y, z]");
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const std::string at = placeOf(placeOf(place, "positions"), std::to_string(i));
    const json& p = positions[i];
    if (!p.is_array() || p.size() != 3) throw SceneError(at, "expected [x, y, z]");
    draw.mesh.positions.push_back({readCoordinate(p[0], placeOf(at, "0")), readCoordinate(p[1], placeOf(at, "1")),
                                   readCoordinate(p[2], placeOf(at, "2"))});
    draw.mesh.colours.push_back(colour);
  }
  if (d.contains("colours")) {
    const json& colours = d["colours"];
    if (!colours.is_array() || colours.size() != positions.size()) {
      throw SceneError(placeOf(place, "colours"), "expected one colour per position (" + std::to_string(positions.size()) + ")");
    }
    for (std::size_t i = 0; i < colours.size(); ++i) {
      draw.mesh.colours[i] = readColour(colours[i], placeOf(placeOf(place, "colours"), std::to_string(i)), range);
    }
  }
  if (d.contains("indices")) {
    const json& indices = d["indices"];
    if (!indices.is_array()) throw SceneError(placeOf(place, "indices"), "expected an array of indices");
    for (std::size_t i = 0; i < indices.size(); ++i) {
      const json& index = indices[i];
      if (index.is_string() && index.get<std::string>() == "restart") {
        if (!draw.state.primitiveRestartEnable) {
          throw SceneError(placeOf(placeOf(place, "indices"), std::to_string(i)),
                           "\"restart\" needs \"primitive_restart\": true");
        }
        draw.indices.push_back(softraster::kPrimitiveRestartIndex);
        continue;
      }
      if (!index.is_number_integer() || index.get<std::int64_t>() < 0 ||
          index.get<std::uint64_t>() >= draw.mesh.vertexCount()) {
        throw SceneError(placeOf(placeOf(place, "indices"), std::to_string(i)),
                         "expected an index below " + std::to_string(draw.mesh.vertexCount()));
      }
      draw.indices.push_back(index.get<std::uint32_t>());
    }
  } else {
    draw.indexed = false;  // vertices in order, assembled by the topology
  }
  return draw;
}

// What is wrong with the form of "a.b.c=value", or empty.
std::string overrideFormError(const std::string& assignment) {
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0) return "expected KEY.PATH=VALUE";
  const std::string key = assignment.substr(0, equals);
  if (key.front() == '.' || key.back() == '.' || key.find("..") != std::string::npos) return "empty key component";
  return "";
}

// Applies "a.b.c=value" to the JSON document (json, or ordered_json for sceneFileText); value is
// JSON, or a plain string if it is not.
template <class Json>
void applyOverride(Json& document, const std::string& assignment) {
  if (const std::string error = overrideFormError(assignment); !error.empty()) throw SceneError("--set " + assignment, error);
  const auto equals = assignment.find('=');
  const std::string key = assignment.substr(0, equals);
  const std::string text = assignment.substr(equals + 1);
  Json value = Json::parse(text, nullptr, false);
  if (value.is_discarded()) value = text;
  Json* node = &document;
  std::stringstream parts(key);
  std::string part;
  while (std::getline(parts, part, '.')) {
    if (part.empty()) throw SceneError("--set " + assignment, "empty key component");
    if (node->is_array()) {
      std::size_t index = 0;
      try {
        index = std::stoul(part);
      } catch (const std::exception&) {
        throw SceneError("--set " + assignment, "'" + part + "' is not an array index");
      }
      if (index >= node->size()) throw SceneError("--set " + assignment, "index " + part + " is out of range");
      node = &(*node)[index];
    } else {
      if (!node->is_object()) *node = Json::object();
      node = &(*node)[part];
    }
  }
  *node = value;
}

// At most this many depth passes: a scene has a light or two, not a render graph.
constexpr std::size_t kMaxPasses = 4;

// The names of "passes", in order, for the draws' "shadow_map" to refer to (the passes
// themselves are read after the draws they list; readPasses reports what is malformed).
std::vector<std::string> readPassNames(const json& document) {
  std::vector<std::string> names;
  if (!document.contains("passes") || !document["passes"].is_array()) return names;
  for (const json& pass : document["passes"]) {
    names.push_back(pass.is_object() && pass.contains("name") && pass["name"].is_string() ? pass["name"].get<std::string>()
                                                                                          : std::string());
  }
  return names;
}

// "passes": [{"name", "width", "height", "camera", "draws", "clear_depth", and the pass's
// "cull", "front_face", "depth_bias", "depth_compare"}], each a DepthPass.
void readPasses(const json& passes, Scene& scene) {
  if (!passes.is_array() || passes.empty()) throw SceneError("/passes", "expected a non-empty array of depth passes");
  if (passes.size() > kMaxPasses) {
    throw SceneError("/passes", std::to_string(passes.size()) + " passes, more than " + std::to_string(kMaxPasses));
  }
  const shaders::ShadingModel* depthOnly = shaders::findShadingModel("depth_only");
  for (std::size_t k = 0; k < passes.size(); ++k) {
    const std::string place = "/passes/" + std::to_string(k);
    const json& p = passes[k];
    if (!p.is_object()) throw SceneError(place, "expected an object");
    checkKeys(p, place, {"name", "width", "height", "camera", "draws", "clear_depth", "cull", "front_face",
                         "depth_bias", "depth_compare"});
    DepthPass pass;
    if (!p.contains("name")) throw SceneError(place, "needs \"name\" (what a draw's \"shadow_map\" calls it)");
    pass.name = readString(p, "name", place, "");
    for (const DepthPass& other : scene.passes) {
      if (other.name == pass.name) throw SceneError(placeOf(place, "name"), "two passes are called '" + pass.name + "'");
    }
    pass.width = static_cast<std::uint32_t>(readCount(p, "width", place, pass.width, kMaxFramebufferSize));
    pass.height = static_cast<std::uint32_t>(readCount(p, "height", place, pass.height, kMaxFramebufferSize));
    if (pass.width == 0 || pass.height == 0) throw SceneError(place, "width and height must be in 1..8192");
    pass.clearDepth = readFloat(p, "clear_depth", place, pass.clearDepth);
    if (!(pass.clearDepth >= 0 && pass.clearDepth <= 1)) throw SceneError(placeOf(place, "clear_depth"), "must be in [0, 1]");
    if (!p.contains("camera")) throw SceneError(place, "needs \"camera\" (the light's view, as the scene's \"camera\")");
    CameraSettings settings;
    pass.camera = readCamera(p["camera"], placeOf(place, "camera"), static_cast<int>(pass.width),
                             static_cast<int>(pass.height), settings);
    if (!isFinite(roundedToFloat(pass.camera.projection * pass.camera.view))) {
      throw SceneError(placeOf(place, "camera"), "its matrices are not finite in float");
    }
    readDrawState(p, place, pass.state);
    pass.shading = depthOnly;
    if (p.contains("draws")) {
      const json& names = p["draws"];
      const std::string at = placeOf(place, "draws");
      if (!names.is_array() || names.empty()) throw SceneError(at, "expected a non-empty array of draw names");
      for (std::size_t n = 0; n < names.size(); ++n) {
        const std::string nameAt = placeOf(at, std::to_string(n));
        if (!names[n].is_string()) throw SceneError(nameAt, "expected a draw's name");
        const std::string name = names[n].get<std::string>();
        std::size_t found = scene.draws.size(), matches = 0;
        for (std::size_t i = 0; i < scene.draws.size(); ++i) {
          if (scene.draws[i].name == name) found = matches++ == 0 ? i : found;
        }
        if (matches == 0) throw SceneError(nameAt, "no draw is called '" + name + "'");
        if (matches > 1) throw SceneError(nameAt, std::to_string(matches) + " draws are called '" + name + "'");
        pass.draws.push_back(found);
      }
    } else {
      for (std::size_t i = 0; i < scene.draws.size(); ++i) pass.draws.push_back(i);
    }
    for (std::size_t i : pass.draws) {
      if (!isFinite(passDrawParameters(pass, scene.draws[i]).modelViewProjection)) {
        throw SceneError(place, "draw '" + scene.draws[i].name + "': the pass's model-view-projection matrix is not finite in float");
      }
    }
    scene.passes.push_back(std::move(pass));
    for (std::size_t i = 0; i < scene.draws.size(); ++i) {
      for (const Draw::Texture& t : scene.draws[i].textures) {
        if (t.pass == static_cast<int>(k) && !isFinite(drawParameters(scene, scene.draws[i]).modelToShadow)) {
          throw SceneError("/draws/" + std::to_string(i) + "/shadow_map", "the matrix to the pass's clip space is not finite in float");
        }
      }
    }
  }
}

Scene readScene(json& document, const std::filesystem::path& path, const std::vector<std::string>& overrides) {
  for (const std::string& assignment : overrides) applyOverride(document, assignment);
  checkKeys(document, "", {"description", "framebuffer", "camera", "time", "light", "passes", "draws", "tolerance"});
  Scene scene;
  scene.path = path;
  scene.description = readString(document, "description", "", "");

  if (document.contains("framebuffer")) {
    const json& fb = document["framebuffer"];
    checkKeys(fb, "/framebuffer",
              {"width", "height", "clear_colour", "clear_depth", "clear_stencil", "colour_format", "depth_format",
               "samples", "more_colour_attachments"});
    scene.samples = static_cast<std::uint32_t>(readCount(fb, "samples", "/framebuffer", 1, 64));
    if (scene.samples != 1 && scene.samples != 4) throw SceneError("/framebuffer/samples", "must be 1 or 4");
    const std::vector<std::pair<const char*, softraster::ColourFormat>> colourFormats = {
        {"r8g8b8a8_unorm", softraster::ColourFormat::R8G8B8A8Unorm},
        {"b8g8r8a8_unorm", softraster::ColourFormat::B8G8R8A8Unorm},
        {"r8g8b8a8_srgb", softraster::ColourFormat::R8G8B8A8Srgb},
        {"b8g8r8a8_srgb", softraster::ColourFormat::B8G8R8A8Srgb},
        {"a2b10g10r10_unorm", softraster::ColourFormat::A2B10G10R10Unorm},
        {"r16g16b16a16_sfloat", softraster::ColourFormat::R16G16B16A16Sfloat},
        {"r32g32b32a32_sfloat", softraster::ColourFormat::R32G32B32A32Sfloat}};
    scene.colourFormat = readEnum(fb, "colour_format", "/framebuffer", scene.colourFormat, colourFormats);
    scene.depthFormat = readEnum(fb, "depth_format", "/framebuffer", scene.depthFormat,
                                 {{"d16_unorm", softraster::DepthFormat::D16Unorm},
                                  {"x8_d24_unorm", softraster::DepthFormat::X8D24UnormPack32},
                                  {"d32_sfloat", softraster::DepthFormat::D32Sfloat},
                                  {"d24_unorm_s8_uint", softraster::DepthFormat::D24UnormS8Uint},
                                  {"d32_sfloat_s8_uint", softraster::DepthFormat::D32SfloatS8Uint}});
    scene.width = static_cast<std::uint32_t>(readCount(fb, "width", "/framebuffer", scene.width, kMaxFramebufferSize));
    scene.height = static_cast<std::uint32_t>(readCount(fb, "height", "/framebuffer", scene.height, kMaxFramebufferSize));
    if (scene.width == 0 || scene.height == 0) throw SceneError("/framebuffer", "width and height must be in 1..8192");
    if (fb.contains("clear_colour"))
      scene.clearColour = readColour(fb["clear_colour"], "/framebuffer/clear_colour", colourRange(scene.colourFormat));
    if (fb.contains("more_colour_attachments")) {  // colour attachments 1..: format and clear colour each
      const std::string mp = "/framebuffer/more_colour_attachments";
      const json& more = fb["more_colour_attachments"];
      if (!more.is_array() || more.size() > softraster::kMaxColourAttachments - 1) {
        throw SceneError(mp, "expected an array of at most " + std::to_string(softraster::kMaxColourAttachments - 1) +
                                 " attachments (lavapipe's maxColorAttachments is " +
                                 std::to_string(softraster::kMaxColourAttachments) + ")");
      }
      for (std::size_t a = 0; a < more.size(); ++a) {
        const std::string ap = mp + "/" + std::to_string(a);
        checkKeys(more[a], ap, {"colour_format", "clear_colour"});
        SceneColourAttachment& attachment = scene.moreColour.emplace_back();
        attachment.format = readEnum(more[a], "colour_format", ap, attachment.format, colourFormats);
        attachment.clearColour = scene.clearColour;
        if (more[a].contains("clear_colour")) {
          attachment.clearColour =
              readColour(more[a]["clear_colour"], placeOf(ap, "clear_colour"), colourRange(attachment.format));
        } else if (colourRange(attachment.format) == ColourRange::Unit) {
          const softraster::Vec4& c = scene.clearColour;
          for (float v : {c.x, c.y, c.z, c.w}) {
            if (!(v >= 0 && v <= 1)) {
              throw SceneError(ap, "needs its own clear_colour in [0, 1] (the framebuffer's is not)");
            }
          }
        }
      }
    }
    scene.clearDepth = readFloat(fb, "clear_depth", "/framebuffer", scene.clearDepth);
    if (!(scene.clearDepth >= 0 && scene.clearDepth <= 1)) throw SceneError("/framebuffer/clear_depth", "must be in [0, 1]");
    scene.clearStencil = static_cast<std::uint8_t>(readCount(fb, "clear_stencil", "/framebuffer", 0, 255));
    if (fb.contains("clear_stencil") && !softraster::hasStencil(scene.depthFormat)) {
      throw SceneError("/framebuffer/clear_stencil", "needs a depth_format with stencil (d24_unorm_s8_uint or d32_sfloat_s8_uint)");
    }
  }

  scene.camera = readCamera(document.contains("camera") ? document["camera"] : json::object(), "/camera",
                            static_cast<int>(scene.width), static_cast<int>(scene.height), scene.cameraSettings);
  scene.viewProjection = roundedToFloat(scene.camera.projection * scene.camera.view);
  if (!isFinite(scene.viewProjection)) {
    throw SceneError("/camera", "its matrices are not finite in float (a value too large for the camera's maths)");
  }
  scene.time = readNumber(document, "time", "", 0);
  if (!std::isfinite(scene.time)) throw SceneError("/time", "must be finite");
  if (document.contains("light")) {
    const json& l = document["light"];
    checkKeys(l, "/light", {"position", "power", "colour"});
    scene.light.position = readVec3(l, "position", "/light", scene.light.position);
    scene.light.power = readVec3(l, "power", "/light", scene.light.power);
    scene.light.colour = readVec3(l, "colour", "/light", scene.light.colour);
    for (const auto* v : {&scene.light.position, &scene.light.power, &scene.light.colour}) {
      for (double c : *v) {
        if (!std::isfinite(c)) throw SceneError("/light", "every value must be finite");
      }
    }
  }

  if (!document.contains("draws") || !document["draws"].is_array() || document["draws"].empty()) {
    throw SceneError("/draws", "expected a non-empty array of draws");
  }
  const json& draws = document["draws"];
  if (draws.size() > kMaxDraws) {
    throw SceneError("/draws", std::to_string(draws.size()) + " draws, more than " + std::to_string(kMaxDraws));
  }
  const std::vector<std::string> passNames = readPassNames(document);
  std::size_t vertices = 0;
  TextureCache textures;
  for (std::size_t i = 0; i < draws.size(); ++i) {
    const std::string place = "/draws/" + std::to_string(i);
    scene.draws.push_back(
        readDraw(draws[i], place, path.parent_path(), scene.time, textures, passNames, colourRange(scene.colourFormat)));
    const Draw& draw = scene.draws.back();
    const std::uint32_t attachments = 1 + static_cast<std::uint32_t>(scene.moreColour.size());
    for (std::uint32_t a = draw.shading->colourOutputs; a < attachments; ++a) {
      if (softraster::attachmentBlend(draw.state, a).colorWriteMask != 0) {
        throw SceneError(placeOf(place, "shading"),
                         "'" + std::string(draw.shading->name) + "' writes " +
                             std::to_string(draw.shading->colourOutputs) + " colour output(s) but the framebuffer has " +
                             std::to_string(attachments) +
                             " colour attachments, and Vulkan leaves an attachment without an output undefined: "
                             "give more_blend/" + std::to_string(a - 1) +
                             " \"write_mask\": \"\" or use a model with more outputs");
      }
    }
    if (draw.state.depth.stencilTestEnable && !softraster::hasStencil(scene.depthFormat)) {
      throw SceneError(placeOf(place, "stencil"),
                       "needs a framebuffer depth_format with stencil (d24_unorm_s8_uint or d32_sfloat_s8_uint)");
    }
    vertices += draw.indexed ? draw.indices.size() : draw.mesh.vertexCount();
    if (vertices > kMaxSceneVertices) {
      throw SceneError(place, "the scene's draws have " + std::to_string(vertices) + " vertices so far, more than " +
                                  std::to_string(kMaxSceneVertices));
    }
    if (!isFinite(drawParameters(scene, draw).modelViewProjection)) {
      throw SceneError(placeOf(place, "transform"), "the model-view-projection matrix is not finite in float");
    }
  }

  if (document.contains("passes")) readPasses(document["passes"], scene);

  if (document.contains("tolerance")) {
    const json& t = document["tolerance"];
    checkKeys(t, "/tolerance", {"colour", "depth", "coverage_mismatches", "colour_pixels_over", "depth_pixels_over"});
    Tolerance& tol = scene.tolerance;
    tol.colourThreshold =
        static_cast<int>(readCount(t, "colour", "/tolerance", static_cast<std::uint64_t>(tol.colourThreshold), 255));
    tol.depthThreshold = readNumber(t, "depth", "/tolerance", tol.depthThreshold);
    if (!(tol.depthThreshold >= 0 && tol.depthThreshold <= 1)) throw SceneError("/tolerance/depth", "must be in [0, 1]");
    tol.maxCoverageMismatches = readCount(t, "coverage_mismatches", "/tolerance", tol.maxCoverageMismatches);
    tol.maxColourPixelsOver = readCount(t, "colour_pixels_over", "/tolerance", tol.maxColourPixelsOver);
    tol.maxDepthPixelsOver = readCount(t, "depth_pixels_over", "/tolerance", tol.maxDepthPixelsOver);
  }
  return scene;
}

}  // namespace

shaders::DrawParameters drawParameters(const Scene& scene, const Draw& draw) {
  shaders::DrawParameters p;
  const glm::dmat4 modelView = scene.camera.view * draw.model;
  p.modelViewProjection = roundedToFloat(scene.camera.projection * modelView);
  p.modelToWorld = roundedToFloat(draw.model);
  p.normalToWorld = normalMatrix(draw.model);
  p.modelToCamera = roundedToFloat(modelView);
  p.normalToCamera = normalMatrix(modelView);
  const glm::dvec4 light(scene.light.position[0], scene.light.position[1], scene.light.position[2], 1.0);
  p.light.positionInWorld = roundedToFloat(light);
  p.light.positionInCamera = roundedToFloat(scene.camera.view * light);
  const auto rgb = [](const std::array<double, 3>& c) { return roundedToFloat(glm::dvec4(c[0], c[1], c[2], 0.0)); };
  p.light.power = rgb(scene.light.power);
  p.light.colour = rgb(scene.light.colour);
  p.material = draw.material;
  p.pointSize = draw.pointSize;
  for (std::size_t i = 0; i < draw.textures.size() && i < p.textures.size(); ++i) {
    const Draw::Texture& t = draw.textures[i];
    p.textures[i] = {t.texture.get(), t.sampler};  // a pass's depth: null here, the renderer's image
    if (t.pass >= 0 && static_cast<std::size_t>(t.pass) < scene.passes.size()) {
      const CameraMatrices& light = scene.passes[static_cast<std::size_t>(t.pass)].camera;
      p.modelToShadow = roundedToFloat(light.projection * (light.view * draw.model));
    }
  }
  p.shadowBias = draw.shadowBias;
  switch (scene.cameraSettings.type) {
    case CameraSettings::Type::Pinhole: p.nearPlane = static_cast<float>(scene.cameraSettings.pinhole.nearPlane); break;
    case CameraSettings::Type::LookAt: p.nearPlane = static_cast<float>(scene.cameraSettings.lookAt.nearPlane); break;
    case CameraSettings::Type::ClipSpace: p.nearPlane = 1.0f; break;
  }
  return p;
}

shaders::DrawParameters passDrawParameters(const DepthPass& pass, const Draw& draw) {
  shaders::DrawParameters p;
  p.modelViewProjection = roundedToFloat(pass.camera.projection * (pass.camera.view * draw.model));
  p.pointSize = draw.pointSize;
  return p;
}

softraster::Status checkOverride(const std::string& assignment) {
  const std::string error = overrideFormError(assignment);
  if (error.empty()) return {};
  return softraster::Status::error("--set " + assignment + ": " + error);
}

namespace {

// nlohmann's messages start "[json.exception.parse_error.101] "; the rest is the one line.
std::string withoutId(const json::exception& e) {
  const std::string message = e.what();
  const auto end = message.find("] ");
  return message.rfind("[json.exception.", 0) == 0 && end != std::string::npos ? message.substr(end + 2) : message;
}

// The scene file parsed as JSON (json, or ordered_json to write it back in its own order); the
// error is "FILE: what is wrong".
template <class Json>
softraster::Result<Json> parseSceneFile(const std::filesystem::path& path) {
  using softraster::Status;
  if (const Status readable = checkInputFile(path); !readable) {
    return Status::error(path.string() + ": cannot open scene file: " + readable.message());
  }
  std::ifstream file(path);
  if (!file) return Status::error(path.string() + ": cannot open scene file");
  try {
    return Json::parse(file);  // parse_error: "parse error at line 3, column 5: ..."; out_of_range: 1e400
  } catch (const json::exception& e) {
    return Status::error(path.string() + ": " + withoutId(e));
  }
}

// JSON on one line with a space after each ',' and ':' (the scene files' own style for values).
std::string oneLine(const nlohmann::ordered_json& value) {
  if (value.is_object()) {
    std::string out = "{ ";
    bool first = true;
    for (const auto& [key, item] : value.items()) {
      out += (first ? "" : ", ") + nlohmann::ordered_json(key).dump() + ": " + oneLine(item);
      first = false;
    }
    return first ? "{}" : out + " }";
  }
  if (value.is_array()) {
    std::string out = "[";
    for (std::size_t i = 0; i < value.size(); ++i) out += (i ? ", " : "") + oneLine(value[i]);
    return out + "]";
  }
  return value.dump();  // numbers as nlohmann writes them: the shortest text that reads back the same double
}

// A scene document as the scene files are laid out: one top-level field per line, one draw per line.
std::string sceneLayout(const nlohmann::ordered_json& document) {
  if (!document.is_object()) return oneLine(document) + "\n";
  std::string out = "{\n";
  std::size_t i = 0;
  for (const auto& [key, value] : document.items()) {
    out += "  " + nlohmann::ordered_json(key).dump() + ": ";
    if (key == "draws" && value.is_array() && !value.empty()) {
      out += "[\n";
      for (std::size_t d = 0; d < value.size(); ++d) out += "    " + oneLine(value[d]) + (d + 1 < value.size() ? ",\n" : "\n");
      out += "  ]";
    } else {
      out += oneLine(value);
    }
    out += ++i < document.size() ? ",\n" : "\n";
  }
  return out + "}\n";
}

}  // namespace

softraster::Result<Scene> loadScene(const std::filesystem::path& path, const std::vector<std::string>& overrides) {
  using softraster::Status;
  auto parsed = parseSceneFile<json>(path);
  if (!parsed) return parsed.status();
  json& document = *parsed;
  try {
    return readScene(document, path, overrides);
  } catch (const SceneError& e) {
    return Status::error(path.string() + ": " + (e.place.empty() ? "/" : e.place) + ": " + e.what());
  } catch (const json::exception& e) {
    return Status::error(path.string() + ": " + withoutId(e));
  } catch (const std::bad_alloc&) {
    return Status::error(path.string() + ": out of memory while loading the scene");
  } catch (const std::exception& e) {
    return Status::error(path.string() + ": " + e.what());
  }
}

softraster::Result<std::string> sceneFileText(const std::filesystem::path& path, const std::vector<std::string>& overrides,
                                              const std::filesystem::path& directory, const std::string& description) {
  using softraster::Status;
  using ordered = nlohmann::ordered_json;
  auto parsed = parseSceneFile<ordered>(path);
  if (!parsed) return parsed.status();
  ordered document = std::move(*parsed);
  try {
    for (const std::string& assignment : overrides) applyOverride(document, assignment);
  } catch (const SceneError& e) {
    return Status::error(path.string() + ": " + (e.place.empty() ? "/" : e.place) + ": " + e.what());
  } catch (const json::exception& e) {
    return Status::error(path.string() + ": " + withoutId(e));
  }
  if (!document.is_object()) return Status::error(path.string() + ": /: expected an object");
  if (!description.empty()) {
    ordered out = ordered::object();  // the description first, as every scene file has it
    out["description"] = description;
    for (auto& [key, value] : document.items()) {
      if (key != "description") out[key] = std::move(value);
    }
    document = std::move(out);
  }
  // File paths are relative to the scene file (a draw's "obj", its "texture"'s "file"): make them
  // relative to where the new one goes.
  if (document.contains("draws") && document["draws"].is_array()) {
    std::error_code error;
    const std::filesystem::path to = std::filesystem::weakly_canonical(std::filesystem::absolute(directory, error), error);
    const auto rebase = [&](ordered& object, const char* key) {
      if (!object.is_object() || !object.contains(key) || !object[key].is_string()) return;
      const std::filesystem::path file = std::filesystem::weakly_canonical(
          std::filesystem::absolute(path.parent_path() / object[key].get<std::string>(), error), error);
      const std::filesystem::path relative = file.lexically_relative(to);
      object[key] = (relative.empty() ? file : relative).generic_string();
    };
    for (ordered& draw : document["draws"]) {
      rebase(draw, "obj");
      if (draw.is_object() && draw.contains("texture")) rebase(draw["texture"], "file");
    }
  }
  return sceneLayout(document);
}

}  // namespace crosscheck

// Scene: what one conformance case draws and how closely the two renderers must agree.
// Loaded from a JSON scene file (format: scenes/README.md). A scene file states only what
// differs from the defaults; every error names the file, the place and what is wrong.
// A draw's "shading" names a row of the table of shading models (shaders/shading_models.hpp);
// its mesh is kept model-neutral (shaders/draw_inputs.hpp) for that row to pack. A mesh comes
// from an OBJ file, from inline positions or from a procedural sphere ("sphere": a UV sphere
// made at load time, so large benchmark meshes need no large files).
// A scene may render depth passes first ("passes": shadow maps) that its draws sample.
// Deliberately no scene graph: a scene is a camera plus a flat list of draws.
#pragma once

#include "scene/camera.hpp"
#include "scene/tolerance.hpp"

#include <softraster/framebuffer.hpp>
#include <softraster/math.hpp>
#include <softraster/state.hpp>
#include <softraster/texture.hpp>
#include <softraster/status.hpp>

#include <draw_inputs.hpp>
#include <shading_models.hpp>

#include <glm/mat4x4.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <memory>
#include <vector>

namespace crosscheck {

// One draw: a mesh in model-neutral form, drawn with the pipeline state and the shading model
// (a row of shaders/shading_models.hpp) the scene file names.
struct Draw {
  std::string name;
  const shaders::ShadingModel* shading = nullptr;  // never null in a loaded scene
  softraster::PipelineState state;
  shaders::Mesh mesh;                   // positions, a colour per vertex, normals if the model reads them
  bool indexed = true;                  // false: vertices are drawn in order (vkCmdDraw)
  float pointSize = 1.0f;               // the shader's gl_PointSize (a uniform)
  std::vector<std::uint32_t> indices;
  glm::dmat4 model{1.0};                // object -> world: "transform" at the scene's time
  bool spins = false;                   // "transform.spin" is not zero: the draw moves with the time
  shaders::Material material;           // what the lit models read beyond the vertex colours
  // What a textured model samples ("texture", then "normal_map"): the texture (shared by draws
  // naming the same file, format and mip choice) and the sampler. Empty for models that sample nothing.
  // A model that samples a shadow map ("shadow_map") has one entry with no texture: `pass` names
  // the depth pass (Scene::passes) whose depth it samples, rendered earlier in the same frame.
  struct Texture {
    std::shared_ptr<const softraster::Texture> texture;
    softraster::SamplerState sampler;
    int pass = -1;
  };
  std::vector<Texture> textures;
  float shadowBias = 0.0f;  // "shadow_map"'s "bias": subtracted from the reference depth
};

// A depth pass ("passes"): the named draws' meshes drawn again before the scene's own draws, with
// the depth_only model from the pass's own camera, into a D32_SFLOAT image of its own size that
// later draws sample as a shadow map. Only depth: no colour, and its draws sample nothing.
struct DepthPass {
  std::string name;
  std::uint32_t width = 512, height = 512;
  float clearDepth = 1.0f;
  CameraMatrices camera;               // the light's view and projection
  softraster::PipelineState state;     // cull, front face, depth bias and compare for every draw of the pass
  std::vector<std::size_t> draws;      // indices into Scene::draws, drawn in this order
  const shaders::ShadingModel* shading = nullptr;  // depth_only
};

// The scene's one point light (world space), read by the lit models.
struct SceneLight {
  std::array<double, 3> position{0, -0.5, -0.7};
  std::array<double, 3> power{14, 14, 14};  // the course's P
  std::array<double, 3> colour{1, 1, 1};    // Phong's light colour
};

// The camera as the scene file states it, defaults filled in: what `Scene::camera` was computed
// from, and what a tool edits (crosscheck view) to write the same change back as --set overrides.
struct CameraSettings {
  enum class Type { Pinhole, LookAt, ClipSpace };
  Type type = Type::Pinhole;
  PinholeCamera pinhole;  // for Type::Pinhole
  LookAtCamera lookAt;    // for Type::LookAt
};

// A colour attachment after the first ("more_colour_attachments"): the fragment output location
// it takes is its place + 1; each draw's "more_blend" blends it.
struct SceneColourAttachment {
  softraster::ColourFormat format = softraster::ColourFormat::R8G8B8A8Unorm;
  softraster::Vec4 clearColour{0, 0, 0, 1};
};

struct Scene {
  std::filesystem::path path;
  std::string description;
  std::uint32_t width = 320, height = 240;
  softraster::Vec4 clearColour{0, 0, 0, 1};
  float clearDepth = 1.0f;
  std::uint8_t clearStencil = 0;  // with a depth/stencil format
  softraster::ColourFormat colourFormat = softraster::ColourFormat::R8G8B8A8Unorm;
  std::vector<SceneColourAttachment> moreColour;  // colour attachments 1..
  softraster::DepthFormat depthFormat = softraster::DepthFormat::D32Sfloat;
  std::uint32_t samples = 1;  // 1 or 4 (MSAA: compared after the resolve; depth and stencil via sample 0)
  CameraMatrices camera;      // view and projection, double precision
  CameraSettings cameraSettings;  // what the file says `camera` is made from
  softraster::Mat4 viewProjection = softraster::Mat4::identity();  // projection * view, rounded once
  double time = 0;            // drives each draw's "spin"
  SceneLight light;
  std::vector<Draw> draws;
  std::vector<DepthPass> passes;  // rendered first, in order
  Tolerance tolerance;
};

// What the draw's shading model reads besides its mesh: its matrices (each product taken in
// double and rounded to float once), the light in world and camera space, the material.
shaders::DrawParameters drawParameters(const Scene& scene, const Draw& draw);
// What a depth pass's model reads for one of its draws: the draw's object -> the pass's clip space.
shaders::DrawParameters passDrawParameters(const DepthPass& pass, const Draw& draw);

// Loads and validates a scene. `overrides` are "key.path=JSON value" assignments applied to the
// file's JSON before it is read (e.g. "camera.yaw=90"). The error is one line:
// "FILE: PLACE: what is wrong".
softraster::Result<Scene> loadScene(const std::filesystem::path& path, const std::vector<std::string>& overrides = {});

// The scene file's JSON with `overrides` applied as loadScene applies them (keys in the file's
// order), to be written as a new scene file in `directory`: the files a draw names (its "obj",
// its "texture"'s "file") rewritten relative to `directory`, and "description" replaced by
// `description` when it is not empty.
// The text is not checked as a scene (load it to check it); the error is loadScene's one line
// for a file that cannot be read or parsed, or an override that cannot be applied.
softraster::Result<std::string> sceneFileText(const std::filesystem::path& path, const std::vector<std::string>& overrides,
                                              const std::filesystem::path& directory, const std::string& description);

// Whether `assignment` has the KEY.PATH=VALUE form (before any scene is read, so a suite run can
// refuse a malformed --set at once); the error is "--set ASSIGNMENT: what is wrong".
softraster::Status checkOverride(const std::string& assignment);

}  // namespace crosscheck

// Cameras of the course material, as a view matrix (world to camera space) and a projection
// matrix (camera to Vulkan's clip space: x right, y down, depth 0 at the near plane and 1 at the
// far plane), both in double precision (GLM); the scene rounds each product to float once.
// Camera space follows the course's pinhole model: x right, y down, z forward; world space uses
// the same axes unless a look-at camera says which way is up.
// Deliberately no orthographic camera and no lens shift until a scene needs one.
#pragma once

#include <glm/mat4x4.hpp>

#include <array>

namespace crosscheck {

// Pinhole camera: position, yaw (about the y axis, positive turns right), pitch (about the
// x axis, positive looks up) and focal length in pixels; the image centre is the principal point.
struct PinholeCamera {
  std::array<double, 3> position{0, 0, 0};
  double yawDegrees = 0, pitchDegrees = 0;
  double focalLengthPixels = 0;
  double nearPlane = 0.1, farPlane = 100;
};

// Perspective camera: vertical field of view, aspect (width / height), near/far, look-at.
struct LookAtCamera {
  std::array<double, 3> eye{0, 0, -1}, target{0, 0, 0}, up{0, -1, 0};
  double fovYDegrees = 60, aspect = 0;  // aspect 0: the framebuffer's
  double nearPlane = 0.1, farPlane = 100;
};

struct CameraMatrices {
  glm::dmat4 view{1.0};        // world -> camera
  glm::dmat4 projection{1.0};  // camera -> clip
};

CameraMatrices cameraMatrices(const PinholeCamera& camera, int width, int height);
CameraMatrices cameraMatrices(const LookAtCamera& camera, int width, int height);

}  // namespace crosscheck

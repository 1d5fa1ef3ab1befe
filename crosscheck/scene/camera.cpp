// Camera matrices (see camera.hpp), with GLM's double-precision vectors and matrices.
#include "scene/camera.hpp"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

namespace crosscheck {
namespace {

glm::dvec3 toVec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

// World-to-camera matrix from the camera's right, down and forward axes and its position
// (GLM is column-major: m[column][row]).
glm::dmat4 viewMatrix(glm::dvec3 right, glm::dvec3 down, glm::dvec3 forward, glm::dvec3 position) {
  glm::dmat4 m(1.0);
  for (int c = 0; c < 3; ++c) {
    m[c][0] = right[c];
    m[c][1] = down[c];
    m[c][2] = forward[c];
  }
  m[3] = glm::dvec4(-glm::dot(right, position), -glm::dot(down, position), -glm::dot(forward, position), 1.0);
  return m;
}

// Perspective projection with x and y scaled by sx and sy; depth [near, far] -> [0, 1].
glm::dmat4 projectionMatrix(double sx, double sy, double nearPlane, double farPlane) {
  const double a = farPlane / (farPlane - nearPlane);
  glm::dmat4 m(0.0);
  m[0][0] = sx;
  m[1][1] = sy;
  m[2][2] = a;
  m[2][3] = 1.0;
  m[3][2] = -nearPlane * a;
  return m;
}

}  // namespace

CameraMatrices cameraMatrices(const PinholeCamera& camera, int width, int height) {
  // Camera-to-world rotation R = R_y(yaw) * R_x(pitch); its columns are the camera axes.
  const double yaw = glm::radians(camera.yawDegrees), pitch = glm::radians(camera.pitchDegrees);
  const double cy = glm::cos(yaw), sy = glm::sin(yaw), cp = glm::cos(pitch), sp = glm::sin(pitch);
  const glm::dvec3 right{cy, 0, -sy};
  const glm::dvec3 down{sy * sp, cp, cy * sp};
  const glm::dvec3 forward{sy * cp, -sp, cy * cp};
  return {viewMatrix(right, down, forward, toVec(camera.position)),
          projectionMatrix(2.0 * camera.focalLengthPixels / width, 2.0 * camera.focalLengthPixels / height,
                           camera.nearPlane, camera.farPlane)};
}

CameraMatrices cameraMatrices(const LookAtCamera& camera, int width, int height) {
  const glm::dvec3 eye = toVec(camera.eye);
  const glm::dvec3 forward = glm::normalize(toVec(camera.target) - eye);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, toVec(camera.up)));
  const glm::dvec3 down = glm::cross(forward, right);
  const double aspect = camera.aspect > 0 ? camera.aspect : static_cast<double>(width) / height;
  const double focal = 1.0 / glm::tan(glm::radians(camera.fovYDegrees) / 2);
  return {viewMatrix(right, down, forward, eye), projectionMatrix(focal / aspect, focal, camera.nearPlane, camera.farPlane)};
}

}  // namespace crosscheck

// Camera matrices (see camera.hpp).
#include "scene/camera.hpp"

#include <cmath>
#include <numbers>

namespace crosscheck {
namespace {

using Vec3d = std::array<double, 3>;
using Mat4d = std::array<std::array<double, 4>, 4>;  // [row][column]

Vec3d sub(Vec3d a, Vec3d b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(Vec3d a, Vec3d b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3d cross(Vec3d a, Vec3d b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3d normalize(Vec3d a) {
  const double length = std::sqrt(dot(a, a));
  return {a[0] / length, a[1] / length, a[2] / length};
}

// World-to-camera matrix from the camera's right, down and forward axes and its position.
Mat4d viewMatrix(Vec3d right, Vec3d down, Vec3d forward, Vec3d position) {
  return {{{right[0], right[1], right[2], -dot(right, position)},
           {down[0], down[1], down[2], -dot(down, position)},
           {forward[0], forward[1], forward[2], -dot(forward, position)},
           {0, 0, 0, 1}}};
}

// Perspective projection with x and y scaled by sx and sy; depth [near, far] -> [0, 1].
Mat4d projectionMatrix(double sx, double sy, double nearPlane, double farPlane) {
  const double a = farPlane / (farPlane - nearPlane);
  return {{{sx, 0, 0, 0}, {0, sy, 0, 0}, {0, 0, a, -nearPlane * a}, {0, 0, 1, 0}}};
}

softraster::Mat4 toFloat(const Mat4d& projection, const Mat4d& view) {
  softraster::Mat4 m;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      double sum = 0;
      for (int k = 0; k < 4; ++k) sum += projection[r][k] * view[k][c];
      m.at(r, c) = static_cast<float>(sum);
    }
  }
  return m;
}

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

}  // namespace

softraster::Mat4 viewProjection(const PinholeCamera& camera, int width, int height) {
  // Camera-to-world rotation R = R_y(yaw) * R_x(pitch); its columns are the camera axes.
  const double cy = std::cos(radians(camera.yawDegrees)), sy = std::sin(radians(camera.yawDegrees));
  const double cp = std::cos(radians(camera.pitchDegrees)), sp = std::sin(radians(camera.pitchDegrees));
  const Vec3d right{cy, 0, -sy};
  const Vec3d down{sy * sp, cp, cy * sp};
  const Vec3d forward{sy * cp, -sp, cy * cp};
  const Mat4d view = viewMatrix(right, down, forward, camera.position);
  const Mat4d projection = projectionMatrix(2.0 * camera.focalLengthPixels / width,
                                            2.0 * camera.focalLengthPixels / height, camera.nearPlane, camera.farPlane);
  return toFloat(projection, view);
}

softraster::Mat4 viewProjection(const LookAtCamera& camera, int width, int height) {
  const Vec3d forward = normalize(sub(camera.target, camera.eye));
  const Vec3d right = normalize(cross(forward, camera.up));
  const Vec3d down = cross(forward, right);
  const Mat4d view = viewMatrix(right, down, forward, camera.eye);
  const double aspect = camera.aspect > 0 ? camera.aspect : static_cast<double>(width) / height;
  const double focal = 1.0 / std::tan(radians(camera.fovYDegrees) / 2);
  return toFloat(projectionMatrix(focal / aspect, focal, camera.nearPlane, camera.farPlane), view);
}

}  // namespace crosscheck

#include "reference/common/view_camera.h"

#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace voxref::ref {

namespace {
constexpr double kPi = 3.14159265358979323846;
double radians(double degrees) { return degrees * kPi / 180.0; }
}  // namespace

CameraBasis cameraBasis(const ViewCamera& c) {
  if (c.width <= 0 || c.height <= 0) throw std::invalid_argument("camera: width and height must be positive");
  if (!(c.fovYDegrees > 0.0 && c.fovYDegrees < 180.0))
    throw std::invalid_argument("camera: fov_y must be in (0, 180) degrees");
  if (!(c.nearPlane > 0.0 && c.nearPlane < c.farPlane)) throw std::invalid_argument("camera: need 0 < near < far");
  const glm::dvec3 view = c.target - c.eye;
  if (glm::length(view) == 0.0) throw std::invalid_argument("camera: eye and target coincide");
  CameraBasis b;
  b.forward = glm::normalize(view);
  const glm::dvec3 r = glm::cross(b.forward, c.up);
  if (glm::length(r) < 1e-12 * glm::length(c.up))
    throw std::invalid_argument("camera: up is parallel to the view direction");
  b.right = glm::normalize(r);
  b.up = glm::cross(b.right, b.forward);
  return b;
}

Ray pixelRay(const ViewCamera& c, double x, double y) {
  const CameraBasis b = cameraBasis(c);
  const double t = std::tan(radians(c.fovYDegrees) / 2.0);
  const double aspect = static_cast<double>(c.width) / c.height;
  // Normalized device coordinates of the point, as glm::perspective maps them.
  const double ndcX = 2.0 * x / c.width - 1.0;
  const double ndcY = 2.0 * y / c.height - 1.0;
  const glm::dvec3 d = b.forward + (ndcX * t * aspect) * b.right + (ndcY * t) * b.up;
  return {c.eye, glm::normalize(d)};
}

double eyeDepth(const ViewCamera& c, const glm::dvec3& p) { return glm::dot(p - c.eye, cameraBasis(c).forward); }

double windowDepth(const ViewCamera& c, double z) {
  // glm::perspective (right handed, clip z in [-1, 1]): z_ndc = (f + n) / (f - n) - 2 f n / ((f - n) z).
  const double n = c.nearPlane, f = c.farPlane;
  const double ndc = (f + n) / (f - n) - 2.0 * f * n / ((f - n) * z);
  return 0.5 * ndc + 0.5;
}

glm::dmat4 viewMatrix(const ViewCamera& c) {
  const CameraBasis b = cameraBasis(c);
  return glm::lookAt(c.eye, c.target, b.up);
}

glm::dmat4 projectionMatrix(const ViewCamera& c) {
  cameraBasis(c);  // validates
  return glm::perspective(radians(c.fovYDegrees), static_cast<double>(c.width) / c.height, c.nearPlane, c.farPlane);
}

ViewCamera orbitCamera(const OrbitPath& path, int frame, const ViewCamera& base) {
  if (path.frames < 1) throw std::invalid_argument("orbit: frames must be at least 1");
  const double s = path.frames == 1 ? 0.0 : static_cast<double>(frame) / (path.frames - 1);
  const double az = radians(path.azimuthStartDegrees + s * (path.azimuthEndDegrees - path.azimuthStartDegrees));
  const double el = radians(path.elevationDegrees);
  ViewCamera c = base;
  c.target = path.center;
  c.eye =
      path.center + path.radius * glm::dvec3(std::cos(el) * std::cos(az), std::sin(el), std::cos(el) * std::sin(az));
  c.up = {0.0, 1.0, 0.0};
  return c;
}

}  // namespace voxref::ref

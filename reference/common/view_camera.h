// A perspective pinhole camera for the isosurface system (Gregorski et al. 2004, section 4): the
// one definition of pixels, rays, view and projection shared by the GL renderer (gpu/), the Embree
// ground truth (fixtures/) and the refinement's view-dependent error (reference/iso/).
//
// Conventions (those of GL, so images compare without flips):
// - pixel (x, y), x in [0, width), y in [0, height), row 0 at the BOTTOM of the image;
// - the ray of pixel (x, y) starts at the eye and passes through the pixel centre
//   (x + 0.5, y + 0.5) on the image plane, like GL's rasterization sample point;
// - depth is eye-space distance along the view axis (not along the ray), the quantity GL's depth
//   buffer encodes; `windowDepth` maps it to GL's [0, 1] window depth for the given near and far
//   planes (glDepthRange(0, 1), the standard perspective projection).
#pragma once

#include <array>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace voxref::ref {

struct ViewCamera {
  glm::dvec3 eye{0.0, 0.0, 5.0};
  glm::dvec3 target{0.0};
  glm::dvec3 up{0.0, 1.0, 0.0};
  double fovYDegrees = 40.0;
  int width = 64, height = 64;
  double nearPlane = 0.1, farPlane = 100.0;
};

struct Ray {
  glm::dvec3 origin;
  glm::dvec3 direction;  // unit length
};

// Orthonormal basis of the camera: right, up, forward (forward points from eye to target).
// Throws std::invalid_argument for a degenerate camera (eye == target, up parallel to the view,
// non-positive size or field of view, near >= far).
struct CameraBasis {
  glm::dvec3 right, up, forward;
};
CameraBasis cameraBasis(const ViewCamera& c);

Ray pixelRay(const ViewCamera& c, double x, double y);  // x, y in pixels; x + 0.5 is a centre
// Eye-space depth of a world point (distance along forward).
double eyeDepth(const ViewCamera& c, const glm::dvec3& p);
// GL window depth in [0, 1] of an eye-space depth z (near..far).
double windowDepth(const ViewCamera& c, double z);

// Column-major matrices as GL takes them (glm::lookAt and glm::perspective in double).
glm::dmat4 viewMatrix(const ViewCamera& c);
glm::dmat4 projectionMatrix(const ViewCamera& c);

// A scripted orbit: frame i of n around `center` at `radius`, azimuth from a0 to a1 degrees, fixed
// elevation. Camera paths are data, so runs are reproducible.
struct OrbitPath {
  glm::dvec3 center{0.0};
  double radius = 3.0, elevationDegrees = 20.0;
  double azimuthStartDegrees = 0.0, azimuthEndDegrees = 90.0;
  int frames = 8;
};
ViewCamera orbitCamera(const OrbitPath& path, int frame, const ViewCamera& base);

}  // namespace voxref::ref

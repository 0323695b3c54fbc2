#include "reference/common/frame_sampling.h"

#include "reference/common/parallel.h"

namespace voxref::ref {

bool insideUnitCube(glm::dvec3 p) {
  return p.x >= 0.0 && p.x <= 1.0 && p.y >= 0.0 && p.y <= 1.0 && p.z >= 0.0 && p.z <= 1.0;
}

SampleStack sampleFrame(const PlaneFrame& frame, const std::function<double(glm::dvec3)>& fn, int threads,
                        const std::function<void(int)>& progress) {
  SampleStack s{frame.width, frame.height, frame.planes,
                std::vector<double>(static_cast<std::size_t>(frame.width) * frame.height * frame.planes, 0.0)};
  parallelFor(
      frame.planes, threads,
      [&](int k) {
        double* plane = s.values.data() + static_cast<std::size_t>(k) * frame.width * frame.height;
        for (int j = 0; j < frame.height; ++j)
          for (int i = 0; i < frame.width; ++i) {
            const glm::dvec3 p = frame.sample(i, j, k);
            plane[static_cast<std::size_t>(i) + static_cast<std::size_t>(frame.width) * j] =
                insideUnitCube(p) ? fn(p) : 0.0;
          }
      },
      progress);
  return s;
}

}  // namespace voxref::ref

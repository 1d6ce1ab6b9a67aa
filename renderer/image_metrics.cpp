#include "renderer/image_metrics.h"

namespace raylab {

double relativeMse(const std::vector<glm::vec3>& image, const std::vector<glm::vec3>& reference) {
  if (image.size() != reference.size() || image.empty()) return -1.0;
  double sum = 0.0;
  for (size_t i = 0; i < image.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      double d = double(image[i][c]) - reference[i][c];
      sum += d * d / (double(reference[i][c]) * reference[i][c] + 0.01);
    }
  return sum / (3.0 * image.size());
}

}  // namespace raylab

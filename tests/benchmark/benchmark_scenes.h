#ifndef WOBBLE_TESTS_BENCHMARK_BENCHMARK_SCENES_H
#define WOBBLE_TESTS_BENCHMARK_BENCHMARK_SCENES_H

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <memory>
#include <string>
#include <vector>

#include "sim/scene.h"

namespace wobble::benchmark {

// The sizes the performance issue names: the paper's curtain (81×81), 128×128 and 256×256
// cloths with structural, shear and bend springs, and the built-in jelly.
struct BenchmarkScene {
  std::string name;
  Scene scene;
};
const std::vector<BenchmarkScene>& benchmark_scenes();

// The plain implementation, as the course's solutions write it and as the seed's
// fast_mass_springs_step_sparse does, with the iteration count as a parameter: A·U, a per-row
// normalize, and SimplicialLLT::solve on the #V by 3 right-hand side. The yardstick.
class ReferenceStepper {
 public:
  explicit ReferenceStepper(const Scene& scene);
  void step(int iterations);
  const Eigen::MatrixXd& positions() const { return current_; }

 private:
  const Scene& scene_;
  Eigen::VectorXd r_;
  Eigen::SparseMatrix<double> M_, A_, C_;
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> prefactorization_;
  Eigen::MatrixXd fext_, previous_, current_, next_;
};

}  // namespace wobble::benchmark

#endif

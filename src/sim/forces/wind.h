#ifndef WOBBLE_SIM_FORCES_WIND_H
#define WOBBLE_SIM_FORCES_WIND_H

#include <Eigen/Core>
#include <memory>

#include "sim/terms/step_term.h"

namespace wobble {

enum class WindModel {
  aerodynamic,  // per-triangle drag and lift from the air's velocity relative to the cloth
  course,       // the course program's W-key force (see CourseWind)
};

struct WindParams {
  bool on = false;
  WindModel model = WindModel::aerodynamic;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // air velocity (m/s)
  double drag = 1.0;                                   // C_d
  double lift = 0.0;                                   // C_l
  double gusts = 0.0;        // relative gust strength in [0, 1]; 0: steady
  double air_density = 1.2;  // ρ (kg/m³)

  // What `--wind` and the W key turn on for a scene that has no wind of its own.
  static WindParams default_breeze();
};

// Throws InputError unless every number is finite and within sim/value_limits.h.
void validate_wind(const WindParams& wind);

// The air's velocity at `point` and simulated time `time` (s): `velocity` scaled by a gust
// factor 1 + gusts·g(s) with g in [−1, 1], a fixed sum of three sines of s = time − (x·û)/|u|,
// so that gusts travel downwind with the air. A pure function of time and place: runs repeat.
Eigen::Vector3d wind_velocity_at(const WindParams& wind, const Eigen::Vector3d& point, double time);

// Aerodynamic wind on the render triangles F (a mesh without triangles feels none). For each
// triangle with area A, unit normal n and velocity v (the mean of its corners' (pᵗ − pᵗ⁻ᐞᵗ)/Δt),
// and u = v_air − v at its centroid:
//   drag  f_d = ½ ρ C_d A |u·n| (u·n) n        (pressure on the face: zero edge-on)
//   lift  f_l = ½ ρ C_l A (u·n) ‖u‖ (n − (n·û)û)   (across the air's flow, in the plane of u
//         and n: ½ ρ C_l A ‖u‖² cos θ sin θ, zero edge-on and face-on)
// each shared equally among the three corners.
class AerodynamicWind : public StepTerm {
 public:
  explicit AerodynamicWind(const WindParams& wind) : wind_(wind) {}
  const char* name() const override { return "wind"; }
  void add_forces(const StepContext& step, Eigen::MatrixXd& fext) override;

 private:
  WindParams wind_;
};

// The course program's wind (its W key), per vertex i with φ = x_i/bbd + t:
//   fext(i,0) = 3 + 1.5(1 + cos 5φ),  fext(i,2) = sin φ,  fext(i,1) += 1 + cos(0.3 + φ)
// x_i the vertex's current x (m), bbd the rest bounding box's diagonal (m), t the simulated time
// at the start of the step (s) in place of the program's clock, so that runs repeat. Forces in N
// whatever the mass, like the course's gravity.
class CourseWind : public StepTerm {
 public:
  explicit CourseWind(double rest_diagonal) : rest_diagonal_(rest_diagonal) {}
  const char* name() const override { return "wind"; }
  void add_forces(const StepContext& step, Eigen::MatrixXd& fext) override;

 private:
  double rest_diagonal_;
};

// The wind of `wind`, course or aerodynamic, or nullptr when it is off; `rest_diagonal` is that
// of the rest shape's bounding box (m), the course wind's scale. Made by the registered factory
// (sim/registered_terms.cpp).
std::unique_ptr<StepTerm> make_wind_force(const WindParams& wind, double rest_diagonal);

}  // namespace wobble

#endif

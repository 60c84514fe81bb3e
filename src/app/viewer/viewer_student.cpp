// wobble --student DIR SCENE: a student's fast_mass_springs_step_sparse on the right of the split
// view, Wobble's on the left, each vertex of the student's side coloured by how far it is from
// Wobble's. The student's step runs in its own process (student_step.h): a crash or an endless
// loop stops the right side with the reason written in its corner, and the viewer goes on.
#include <algorithm>

#include "app/viewer/quantity_colors.h"
#include "app/viewer/viewer.h"
#include "ui/color_legend.h"

namespace wobble {

namespace {

// Below this distance (m) a vertex counts as on Wobble's: rounding differences of two correct
// implementations are far smaller, a wrong step far larger.
constexpr double distance_floor = 1e-6;

}  // namespace

SimulationParams seed_method(SimulationParams params) {
  // What fast_mass_springs_step_sparse does: 50 plain iterations from pᵗ, gravity and the pins,
  // nothing else.
  params.iterations = 50;
  params.chebyshev = false;
  params.first_iterate = FirstIterate::current_positions;
  params.damping = 0.0;
  params.wind.on = false;
  params.contact.colliders.clear();
  return params;
}

void Viewer::start_student() {
  const Simulation& main = *simulation_;
  const SpringNetwork& network = scene_.network;
  const std::vector<int> pins = main.pinned_vertices();
  Eigen::VectorXi b(static_cast<Eigen::Index>(pins.size()));
  for (std::size_t i = 0; i < pins.size(); ++i)
    b(static_cast<Eigen::Index>(i)) = pins[i];
  student_ = std::make_unique<StudentStep>(student_server_, network.V, network.E, main.params().k,
                                           network.m, b, main.params().dt);
  // The right side's shape lives in a simulation that is never stepped, only given the
  // student's positions: it draws, colours and frames like any other side.
  twin_ =
      std::make_unique<Simulation>(network, scene_.pins, main.params(), scene_.initial_velocity);
  twin_->set_state(main.positions(), main.previous_positions());
  twin_warning_ = student_->running() ? "" : student_->error();
  student_distance_ = 0.0;
  panel_.split = true;
  twin_positions_.resize(positions_.size());
  twin_normals_.resize(normals_.size());
  student_colors_.assign(positions_.size(), 0.0f);
}

void Viewer::advance_student() {
  if (!twin_warning_.empty()) return;
  Eigen::MatrixXd next;
  std::string error;
  if (!student_->step(simulation_->external_forces(), twin_->previous_positions(),
                      twin_->positions(), next, error)) {
    twin_warning_ = error;
    return;
  }
  const Eigen::MatrixXd now = twin_->positions();
  try {
    twin_->set_state(next, now);
  } catch (const std::exception& refused) {  // a NaN from the student's step
    twin_warning_ = std::string("the student's step returned ") + refused.what();
    return;
  }
  const Eigen::VectorXd distance = (twin_->positions() - simulation_->positions()).rowwise().norm();
  student_distance_ = distance.maxCoeff();
  const double range = std::max(student_distance_, distance_floor);
  for (Eigen::Index i = 0; i < distance.size(); ++i) {
    const Eigen::Vector3f color = sequential_color(static_cast<float>(distance(i) / range));
    for (int c = 0; c < 3; ++c)
      student_colors_[3 * i + c] = color(c);
  }
}

void Viewer::restart_student() {
  twin_->reset();
  twin_->set_state(simulation_->positions(), simulation_->previous_positions());
  student_distance_ = 0.0;
  std::fill(student_colors_.begin(), student_colors_.end(), 0.0f);
  // A server that crashed or hung is started afresh; one that runs keeps its precomputation.
  if (!student_->running()) start_student();
  twin_warning_ = student_->running() ? "" : student_->error();
}

void Viewer::draw_student_legend(float ui_scale) {
  ColorLegend legend;
  constexpr int samples = 17;
  for (int i = 0; i < samples; ++i) {
    const Eigen::Vector3f color = sequential_color(static_cast<float>(i) / (samples - 1));
    legend.colors.insert(legend.colors.end(), color.data(), color.data() + 3);
  }
  legend.title = "right: distance from Wobble's step (m)";
  legend.low = "0";
  legend.high =
      two_significant_digits(static_cast<float>(std::max(student_distance_, distance_floor)));
  legend.note = student_distance_ <= distance_floor ? "the same as Wobble's (within 1e-6 m)"
                                                    : "largest distance this step";
  LegendClearance clearance;
  clearance.instrument_column = panel_.show_convergence || panel_.show_energy;
  clearance.side_labels = true;
  draw_color_legend(legend, ui_scale, clearance);
}

}  // namespace wobble

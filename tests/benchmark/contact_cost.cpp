#include "contact_cost.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "median.h"
#include "sim/contact/collider_contact_term.h"
#include "sim/shapes/cloth_grid.h"
#include "sim/simulation.h"

namespace wobble::benchmark {

void print_contact_cost() {
  ClothGridOptions options;
  options.resolution = 128;
  SpringNetwork cloth = make_cloth_grid(options);
  cloth.V.col(1).array() += 1.0;
  SimulationParams params;
  params.iterations = 50;
  Collider ground, ball;
  ball.type = ColliderType::sphere;
  ball.center = Eigen::Vector3d(0, 0.5, 0);
  ball.radius = 0.3;
  params.contact.colliders = {ground, ball};
  params.contact.friction = 0.4;
  // The same cloth falling free (no collider), steps 41-80: what sliding over the ball is
  // compared with.
  double free_ms = 0.0;
  {
    SimulationParams free_params = params;
    free_params.contact.colliders.clear();
    Simulation simulation(cloth, {}, free_params);
    std::vector<double> total;
    for (int step = 0; step < 80; ++step) {
      simulation.step();
      if (step >= 40) total.push_back(simulation.last_step_timing().total_ms);
    }
    free_ms = median(total);
  }
  for (const bool windy : {false, true}) {
    params.wind = windy ? WindParams::default_breeze() : WindParams();
    Simulation simulation(cloth, {}, params);
    // Falling onto the ball: the contact set grows, and Q is refactorized when it changes.
    const int factorizations = simulation.numeric_factorizations();
    std::vector<double> landing;
    for (int step = 0; step < 40; ++step) {
      simulation.step();
      landing.push_back(simulation.last_step_timing().total_ms);
    }
    const int landing_factorizations = simulation.numeric_factorizations() - factorizations;
    const int rest_factorizations_before = simulation.numeric_factorizations();
    std::vector<double> total, contact, wind;
    for (int step = 0; step < 40; ++step) {
      simulation.step();
      total.push_back(simulation.last_step_timing().total_ms);
      contact.push_back(simulation.last_step_timing().figure("collider contact", "time"));
      wind.push_back(simulation.last_step_timing().forces_ms);
    }
    const double step_ms = median(total);
    std::printf(
        "contact/128x128 drape%s  %d contacts  step %.2f ms  contact %.3f ms (%.1f%%)  "
        "wind %.3f ms (%.1f%%)\n",
        windy ? " + wind" : "",
        simulation.term<wobble::ColliderContactTerm>()->colliders().contact_count(), step_ms,
        median(contact), 100.0 * median(contact) / step_ms, median(wind),
        100.0 * median(wind) / step_ms);
    std::printf(
        "contact/128x128 drape%s  landing: steps 1-40 median %.2f ms, slowest %.2f ms, Q "
        "refactorized %d times; steps 41-80: %d times\n",
        windy ? " + wind" : "", median(landing), *std::max_element(landing.begin(), landing.end()),
        landing_factorizations, simulation.numeric_factorizations() - rest_factorizations_before);
    if (!windy) {
      std::printf(
          "contact/128x128 drape  sliding (steps 41-80) %.2f ms against the same cloth falling "
          "free %.2f ms: %.2fx; Q refactorized on %d of 80 steps\n",
          step_ms, free_ms, step_ms / free_ms,
          simulation.numeric_factorizations() - factorizations);
    }
  }
}

}  // namespace wobble::benchmark

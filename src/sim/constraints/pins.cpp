#include "pins.h"

#include <stdexcept>
#include <string>

namespace wobble {

Pins::Pins(const std::vector<int>& initial, const Eigen::MatrixXd& rest)
    : initial_(initial), pinned_(rest.rows(), 0), targets_(rest) {
  for (int i : initial_)
    pinned_[i] = 1;
  count_ = static_cast<int>(initial_.size());
}

bool Pins::reset(const Eigen::MatrixXd& rest) {
  targets_ = rest;
  std::vector<char> initial(pinned_.size(), 0);
  for (int i : initial_)
    initial[i] = 1;
  if (initial == pinned_) return false;
  pinned_ = std::move(initial);
  count_ = static_cast<int>(initial_.size());
  return true;
}

bool Pins::pin(int i, const Eigen::RowVector3d& at) {
  check_vertex(i, "pin");
  if (pinned_[i]) return false;
  pinned_[i] = 1;
  ++count_;
  targets_.row(i) = at;
  return true;
}

bool Pins::unpin(int i) {
  check_vertex(i, "unpin");
  if (!pinned_[i]) return false;
  pinned_[i] = 0;
  --count_;
  return true;
}

void Pins::set_target(int i, const Eigen::Vector3d& target) {
  check_vertex(i, "set_pin_target");
  if (!pinned_[i]) {
    throw std::invalid_argument("set_pin_target: vertex " + std::to_string(i) + " is not pinned");
  }
  if (!target.allFinite()) throw std::invalid_argument("set_pin_target: target is not finite");
  targets_.row(i) = target.transpose();
}

void Pins::add_diagonal(const StepContext& /*step*/, Eigen::VectorXd& diagonal) {
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(pinned_.size()); ++i) {
    if (pinned_[i]) diagonal(i) += weight;
  }
}

void Pins::add_fixed_rhs(Eigen::MatrixXd& y) const {
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(pinned_.size()); ++i) {
    if (pinned_[i]) y.row(i) += weight * targets_.row(i);
  }
}

double Pins::add_energy(const StepContext& /*step*/, const Eigen::MatrixXd& p,
                        Eigen::MatrixXd* gradient) const {
  double squared = 0.0;
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(pinned_.size()); ++i) {
    if (!pinned_[i]) continue;
    const Eigen::RowVector3d off = p.row(i) - targets_.row(i);
    squared += off.squaredNorm();
    if (gradient) gradient->row(i) += weight * off;
  }
  return 0.5 * weight * squared;
}

void Pins::check_vertex(int i, const char* what) const {
  if (i < 0 || i >= static_cast<int>(pinned_.size())) {
    throw std::out_of_range(std::string(what) + ": vertex " + std::to_string(i) +
                            " is out of range 0 to " + std::to_string(pinned_.size() - 1));
  }
}

std::vector<int> Pins::list() const {
  std::vector<int> result;
  result.reserve(count_);
  for (std::size_t i = 0; i < pinned_.size(); ++i) {
    if (pinned_[i]) result.push_back(static_cast<int>(i));
  }
  return result;
}

}  // namespace wobble

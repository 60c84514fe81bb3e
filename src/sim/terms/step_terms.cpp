#include "sim/terms/step_terms.h"

#include <cstring>

namespace wobble {

double StepTiming::figure(const char* term, const char* name) const {
  for (const TermFigure& figure : figures) {
    if (std::strcmp(figure.term, term) == 0 && std::strcmp(figure.name, name) == 0)
      return figure.value;
  }
  return 0.0;
}

void StepTerms::set(std::vector<StepTerm*> terms) {
  terms_ = std::move(terms);
  solving_.reserve(terms_.size());
  solving_.clear();
  solving_flags_.assign(terms_.size(), 0);
  in_solve_ = false;
  touching_ = false;
}

void StepTerms::add_forces(const StepContext& step, Eigen::MatrixXd& fext) const {
  for (StepTerm* term : terms_)
    term->add_forces(step, fext);
}

const Eigen::VectorXd& StepTerms::diagonal(const StepContext& step) {
  diagonal_.setZero(step.rest.V.rows());
  for (StepTerm* term : terms_)
    term->add_diagonal(step, diagonal_);
  // Q is then exactly the plain method's when no term puts anything on it.
  if ((diagonal_.array() == 0.0).all()) diagonal_.resize(0);
  return diagonal_;
}

Eigen::SparseMatrix<double> StepTerms::matrix(Eigen::Index vertices) const {
  std::vector<Eigen::Triplet<double>> triplets;
  for (const StepTerm* term : terms_)
    term->add_matrix(triplets);
  Eigen::SparseMatrix<double> K(vertices, vertices);
  K.setFromTriplets(triplets.begin(), triplets.end());
  return K;
}

void StepTerms::add_fixed_rhs(Eigen::MatrixXd& y) const {
  for (const StepTerm* term : terms_)
    term->add_fixed_rhs(y);
}

bool StepTerms::begin_step(const StepContext& step, const Eigen::MatrixXd& first) {
  bool changed = false;
  touching_ = false;
  solving_.clear();
  solving_flags_.assign(terms_.size(), 0);
  for (std::size_t t = 0; t < terms_.size(); ++t) {
    const TermStep begun = terms_[t]->begin_step(step, first);
    changed = changed || begun.diagonal_changed;
    touching_ = touching_ || begun.touching;
    if (begun.in_solve) {
      solving_.push_back(terms_[t]);
      solving_flags_[t] = 1;
    }
  }
  in_solve_ = !solving_.empty();
  return changed;
}

void StepTerms::add_targets(const StepContext& step, const Eigen::MatrixXd& p, Eigen::MatrixXd& rhs,
                            double* energy) const {
  for (std::size_t t = 0; t < terms_.size(); ++t) {
    if (solving_flags_[t]) {
      terms_[t]->add_targets(step, p, rhs, energy);
    } else if (energy) {
      // A term outside the iterations (the pins, in y for the whole step) still has an energy.
      *energy += terms_[t]->add_energy(step, p, nullptr);
    }
  }
}

double StepTerms::add_energy(const StepContext& step, const Eigen::MatrixXd& p,
                             Eigen::MatrixXd* gradient) const {
  double energy = 0.0;
  for (const StepTerm* term : terms_)
    energy += term->add_energy(step, p, gradient);
  return energy;
}

bool StepTerms::limit_iterate(const StepContext& step, Eigen::MatrixXd& p) const {
  bool moved = false;
  for (StepTerm* term : solving_)
    moved = term->limit_iterate(step, p) || moved;
  return moved;
}

void StepTerms::project(const StepContext& step, Eigen::MatrixXd& next) const {
  for (StepTerm* term : terms_)
    term->project(step, next);
}

void StepTerms::end_step() const {
  for (StepTerm* term : terms_)
    term->end_step();
}

bool StepTerms::reset() const {
  bool changed = false;
  for (StepTerm* term : terms_)
    changed = term->reset() || changed;
  return changed;
}

void StepTerms::report(std::vector<TermFigure>& figures) const {
  figures.clear();
  for (const StepTerm* term : terms_)
    term->report(figures);
}

}  // namespace wobble

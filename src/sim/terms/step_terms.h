#ifndef WOBBLE_SIM_TERMS_STEP_TERMS_H
#define WOBBLE_SIM_TERMS_STEP_TERMS_H

#include <Eigen/Core>
#include <vector>

#include "sim/terms/step_term.h"

namespace wobble {

// The step's terms in step order (terms/term_registry.h says which order), and each hook called
// over all of them. The Simulation owns the terms; the list only points at them. What a solver
// asks of the step goes through here, so a solver cannot leave a term out.
class StepTerms {
 public:
  void set(std::vector<StepTerm*> terms);
  const std::vector<StepTerm*>& terms() const { return terms_; }
  // The first term of type Term (a term's own accessors: the colliders, self-contact's flags),
  // or nullptr when none is in the list.
  template <typename Term>
  Term* find() const {
    for (StepTerm* term : terms_) {
      if (auto* found = dynamic_cast<Term*>(term)) return found;
    }
    return nullptr;
  }

  void add_forces(const StepContext& step, Eigen::MatrixXd& fext) const;
  // Every term's weights on Q's diagonal (#V), or empty when none has any.
  const Eigen::VectorXd& diagonal(const StepContext& step);
  // Every term's fixed part of Q (#V by #V), with no entries when none has one.
  Eigen::SparseMatrix<double> matrix(Eigen::Index vertices) const;
  void add_fixed_rhs(Eigen::MatrixXd& y) const;
  // Whether any term's diagonal changed.
  bool begin_step(const StepContext& step, const Eigen::MatrixXd& first);
  // Whether any term acts inside this step's iterations.
  bool in_solve() const { return in_solve_; }
  // Whether the last step touched something (as the terms said at this step's start).
  bool touching() const { return touching_; }
  // The terms in the solve add their targets; `energy`, if given, += every term's energy at p.
  void add_targets(const StepContext& step, const Eigen::MatrixXd& p, Eigen::MatrixXd& rhs,
                   double* energy) const;
  double add_energy(const StepContext& step, const Eigen::MatrixXd& p,
                    Eigen::MatrixXd* gradient) const;
  bool limit_iterate(const StepContext& step, Eigen::MatrixXd& p) const;
  void project(const StepContext& step, Eigen::MatrixXd& next) const;
  // figures = every term's figures of the last step (no allocation once grown).
  void report(std::vector<TermFigure>& figures) const;
  void end_step() const;
  bool reset() const;

 private:
  std::vector<StepTerm*> terms_;
  std::vector<StepTerm*> solving_;   // the terms in_solve() this step
  std::vector<char> solving_flags_;  // the same, by position in terms_
  bool in_solve_ = false;
  bool touching_ = false;
  Eigen::VectorXd diagonal_;
};

}  // namespace wobble

#endif

#ifndef WOBBLE_SIM_VOLUME_TET_ROTATIONS_H
#define WOBBLE_SIM_VOLUME_TET_ROTATIONS_H

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace wobble {

// The rotation nearest to F in the Frobenius norm, among proper rotations (det R = +1): the R
// maximizing tr(RᵀF), U·diag(1, 1, det UVᵀ)·Vᵀ for F = UΣVᵀ. So an inverted F (det F < 0) gets
// a right-handed R, and a term pulling F toward it turns the tetrahedron the right way out.
// Turned toward it from `q`, the last answer (warm start), which receives the new one: Newton's
// update of tr(RᵀF) where it is concave, else Müller et al.'s ("A Robust Method to Extract the
// Rotational Part of Deformations", 2016). Stops after `most` updates, or after a Newton update
// that turned by θ with θ² ≤ `tolerance` (rad), when the next would turn by less than
// `tolerance`.
Eigen::Matrix3d nearest_rotation(const Eigen::Matrix3d& F, Eigen::Quaterniond& q, int most = 20,
                                 double tolerance = 1e-12);

// Every tetrahedron's rotation Rₜ nearest its deformation gradient Fₜ = Ds·Dm⁻¹, kept from one
// call to the next as a warm start, and what it adds to the step: the pull w vₜ Gₜ Rₜᵀ, or the
// gradient w vₜ Gₜ (Fₜ − Rₜ)ᵀ, and the energy (w vₜ/2)‖Fₜ − Rₜ‖²_F (volume_term.h has the math).
// The tetrahedra are kept four to a pack, one in each lane of the processor's vector registers
// (AVX2 where the processor has it, the same bits without), so that a tetrahedron's update, some
// two hundred multiplications and additions, runs on four at once; eight at once in single
// precision for the local-global iterations' pull. A tetrahedron's results do
// not depend on its pack's other lanes, nor on how the packs are shared out.
class TetRotations {
 public:
  // V  #V by 3 rest positions; T  #T by 4 tetrahedra (none flat); weight  #T w vₜ (N·m).
  TetRotations(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T, const Eigen::VectorXd& weight);

  // Whether an update of `most` turns, without the gradient nor the energy, runs in single
  // precision: the local-global iterations' case (one turn, the pull alone), eight tetrahedra a
  // vector. The pull's rounding (a few parts in 10⁸ of it) is far below what the iterations
  // leave; L-BFGS's energy and gradient, and anything asking for the energy, stay in double.
  static bool single_precision(int most, bool gradient, bool energy) {
    return most == 1 && !gradient && !energy;
  }
  // Before updates in that precision (see single_precision), on one thread: the last rotations
  // handed over from the other precision's packs, if it was the other one's turn.
  void prepare(bool single);
  // The packs of that precision: the updates' units.
  long packs(bool single) const {
    return static_cast<long>(single ? single_packs_.size() : packs_.size());
  }
  // Packs [begin, end) of the precision prepare() chose, at the positions p (#V by 3): each
  // rotation turned `most` times toward its Fₜ (fewer once the next Newton update would turn by
  // less than `tolerance` rad: see nearest_rotation), then for each tetrahedron t and corner c the
  // pull, or with `gradient` the gradient (N; see out() and single_out()), and with `energy` its
  // energy for energy().
  void update(const Eigen::MatrixXd& p, long begin, long end, int most, double tolerance,
              bool gradient, bool energy);
  // After a double update: the outputs, corner c of tetrahedron t's coordinate i at
  // out()[at(t, c) + 4i]. After a single one (single_current()): the pulls in float, at
  // single_out()[single_at(t, c) + 8i].
  const double* out() const { return reinterpret_cast<const double*>(out_.data()); }
  static long at(long t, int c) {
    return static_cast<long>(sizeof(Out) / sizeof(double)) * (t / 4) + 12 * c + t % 4;
  }
  const float* single_out() const { return reinterpret_cast<const float*>(single_out_.data()); }
  static long single_at(long t, int c) {
    return static_cast<long>(sizeof(SingleOut) / sizeof(float)) * (t / 8) + 24 * c + t % 8;
  }
  bool single_current() const { return single_current_; }
  // Σₜ of the energies of the last update that asked for them, in the order of t (J).
  double energy() const;
  // Every rotation back to the identity (the rest shape's).
  void reset();

  // The packed data of 4 tetrahedra, lane l the tetrahedron 4·pack + l (the last pack padded
  // with copies of the last tetrahedron, whose results are not written).
  typedef double Lane __attribute__((vector_size(32), aligned(32)));
  struct Pack {
    Lane inverse_rest[9];  // Dm⁻¹, row by row
    Lane weight;           // w vₜ
    Lane q[4];             // Rₜ as a quaternion (w, x, y, z), 1 to 2 long
    Lane R[9];             // and as a matrix, row by row
  };
  // The same of 8 tetrahedra in single precision, lane l the tetrahedron 8·pack + l: the double
  // packs 2·pack and 2·pack + 1 side by side.
  typedef float SingleLane __attribute__((vector_size(32), aligned(32)));
  struct SinglePack {
    SingleLane inverse_rest[9];
    SingleLane weight;
    SingleLane q[4];
    SingleLane R[9];
  };
  // What the last double update gave for a pack of 4.
  struct Out {
    Lane pull[12];  // corner c's coordinate i at 3c + i (N)
    Lane energy;    // J
  };
  // What the last single update gave for a pack of 8: the pulls, as Out's.
  struct SingleOut {
    SingleLane pull[12];
  };

 private:
  std::vector<Pack> packs_;
  std::vector<SinglePack> single_packs_;
  std::vector<Out> out_;               // 2 a single pack
  std::vector<SingleOut> single_out_;  // 1 a single pack
  std::vector<int> corners_;           // 16 a pack of 4: corner c of lane l at 16·pack + 4c + l
  long tets_;
  bool single_current_ = false;  // whether single_packs_ hold the last rotations
};

}  // namespace wobble

#endif

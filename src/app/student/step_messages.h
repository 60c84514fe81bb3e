#ifndef WOBBLE_APP_STUDENT_STEP_MESSAGES_H
#define WOBBLE_APP_STUDENT_STEP_MESSAGES_H

#include <Eigen/Core>
#include <string>
#include <vector>

namespace wobble {

// The viewer's side of src/check/step_server/step_protocol.h: the bytes of its two requests.

// The problem, sent once: V #V by 3 (m), E #E by 2, k (N/m), m #V (kg), b #b, delta_t (s).
std::vector<char> encode_problem(const Eigen::MatrixXd& V, const Eigen::MatrixXi& E, double k,
                                 const Eigen::VectorXd& m, const Eigen::VectorXi& b,
                                 double delta_t);

// One step: fext (N), Uprev and Ucur (m), each #V by 3.
std::vector<char> encode_step(const Eigen::MatrixXd& fext, const Eigen::MatrixXd& Uprev,
                              const Eigen::MatrixXd& Ucur);

// The last non-empty line of a server's output, at most 200 characters; for a failed
// assertion, from "Assertion `" on (its program, file and function say nothing to a student).
std::string last_output_line(std::string text);

}  // namespace wobble

#endif

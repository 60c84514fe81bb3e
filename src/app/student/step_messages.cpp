#include "app/student/step_messages.h"

#include <cstdint>
#include <cstring>

#include "check/step_server/step_protocol.h"

namespace wobble {
namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using RowIndices = Eigen::Matrix<std::int32_t, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

void append(std::vector<char>& message, const void* data, size_t bytes) {
  if (bytes == 0) return;
  const size_t at = message.size();
  message.resize(at + bytes);
  std::memcpy(message.data() + at, data, bytes);
}

void append_header(std::vector<char>& message, const char (&magic)[4], Eigen::Index a,
                   Eigen::Index b, Eigen::Index c) {
  step_protocol::Header header{};
  std::memcpy(header.magic, magic, 4);
  header.a = static_cast<std::int32_t>(a);
  header.b = static_cast<std::int32_t>(b);
  header.c = static_cast<std::int32_t>(c);
  append(message, &header, sizeof header);
}

// Eigen stores columns first; the protocol sends rows first.
void append_rows(std::vector<char>& message, const Eigen::MatrixXd& matrix) {
  const RowMatrix rows = matrix;
  append(message, rows.data(), sizeof(double) * rows.size());
}

void append_indices(std::vector<char>& message, const Eigen::MatrixXi& indices) {
  const RowIndices rows = indices.cast<std::int32_t>();
  append(message, rows.data(), sizeof(std::int32_t) * rows.size());
}

}  // namespace

std::vector<char> encode_problem(const Eigen::MatrixXd& V, const Eigen::MatrixXi& E, double k,
                                 const Eigen::VectorXd& m, const Eigen::VectorXi& b,
                                 double delta_t) {
  std::vector<char> message;
  message.reserve(sizeof(step_protocol::Header) + 2 * sizeof(double) +
                  sizeof(double) * (V.size() + m.size()) +
                  sizeof(std::int32_t) * (E.size() + b.size()));
  append_header(message, step_protocol::kProblem, V.rows(), E.rows(), b.size());
  append(message, &k, sizeof k);
  append(message, &delta_t, sizeof delta_t);
  append_rows(message, V);
  append_indices(message, E);
  append_rows(message, m);
  append_indices(message, b);
  return message;
}

std::vector<char> encode_step(const Eigen::MatrixXd& fext, const Eigen::MatrixXd& Uprev,
                              const Eigen::MatrixXd& Ucur) {
  std::vector<char> message;
  message.reserve(sizeof(step_protocol::Header) +
                  sizeof(double) * (fext.size() + Uprev.size() + Ucur.size()));
  append_header(message, step_protocol::kStep, fext.rows(), 0, 0);
  append_rows(message, fext);
  append_rows(message, Uprev);
  append_rows(message, Ucur);
  return message;
}

std::string last_output_line(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' '))
    text.pop_back();
  const size_t start = text.find_last_of('\n');
  std::string line = start == std::string::npos ? text : text.substr(start + 1);
  const size_t assertion = line.find("Assertion `");
  if (assertion != std::string::npos) line = line.substr(assertion);
  if (line.size() > 200) line = line.substr(0, 200) + "...";
  return line;
}

}  // namespace wobble

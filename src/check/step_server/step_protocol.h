#ifndef WOBBLE_CHECK_STEP_PROTOCOL_H
#define WOBBLE_CHECK_STEP_PROTOCOL_H

#include <cstdint>

// The messages between the viewer (wobble::StudentStep, src/app/student/student_step.h) and the
// step server (step_server_main.cpp, built by scripts/check-assignment.sh --build-step-server) over
// the server's stdin and stdout. Every number is little-endian: int32 counts and indices,
// IEEE doubles; matrices go row by row (x, y, z of vertex 0, then of vertex 1, ...).
//
// Once, viewer → server:  Header{kProblem, #V, #E, #b}, then double k, double delta_t,
//                         V (#V×3), E (#E×2 int32), m (#V), b (#b int32)
//          server → viewer: Header{kReady, status, 0, 0}
// Each step, viewer → server: Header{kStep, #V, 0, 0}, then fext, Uprev, Ucur (#V×3 each)
//          server → viewer: Header{kNext, status, rows, cols}, then
//                           Unext (rows×cols)     when status is kOk,
//                           `rows` bytes of text  when status is kThrew
// The viewer ends the server by closing its end (or with Header{kQuit, 0, 0, 0}).
namespace step_protocol {

struct Header {
  char magic[4];
  std::int32_t a, b, c;
};
static_assert(sizeof(Header) == 16, "the header has no padding");
// Numbers go as they lie in memory, which is the protocol's byte order only on such machines.
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the protocol is little-endian");

constexpr char kProblem[4] = {'W', 'S', 'P', 'P'};
constexpr char kReady[4] = {'W', 'S', 'P', 'R'};
constexpr char kStep[4] = {'W', 'S', 'P', 'S'};
constexpr char kNext[4] = {'W', 'S', 'P', 'N'};
constexpr char kQuit[4] = {'W', 'S', 'P', 'Q'};

// Statuses of kReady and kNext.
constexpr std::int32_t kOk = 0;
constexpr std::int32_t kBadMessage = 1;   // a count or an index out of range
constexpr std::int32_t kNotFactored = 2;  // the reference precomputation failed (Q not SPD)
constexpr std::int32_t kWrongShape = 3;   // Unext is rows×cols, not #V×3
constexpr std::int32_t kThrew = 4;        // the step threw; its what() follows

// Larger problems are refused as malformed, so a corrupt count cannot ask for terabytes.
constexpr std::int32_t kMaxCount = 50000000;

}  // namespace step_protocol

#endif

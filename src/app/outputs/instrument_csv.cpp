#include "app/outputs/instrument_csv.h"

#include <charconv>

#include "io/atomic_file.h"
#include "sim/input_error.h"
#include "sim/instruments/frame_energy.h"

namespace wobble {

const char* const convergence_csv_header = "frame,iteration,energy,gradient_norm,solver\n";

void append_csv_value(std::string& out, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.push_back(',');
  out.append(buffer, result.ptr);
}

void append_convergence_rows(std::string& out, long step, const ConvergenceTrace& trace) {
  for (int i = 0; i <= trace.iterations(); ++i) {
    out += std::to_string(step);
    out += ',';
    out += std::to_string(i);
    append_csv_value(out, trace.energy[i]);
    append_csv_value(out, trace.gradient_norm[i]);
    out.push_back(',');
    out += trace.solver;
    out.push_back('\n');
  }
}

namespace {

void append_value(std::string& out, double value) {
  append_csv_value(out, value);
}

void append_energy_row(std::string& out, long frame, const Simulation& simulation) {
  const FrameEnergy energy = frame_energy(simulation);
  out += std::to_string(frame);
  append_value(out, simulation.time());
  append_value(out, energy.kinetic);
  append_value(out, energy.spring);
  append_value(out, energy.gravity);
  append_value(out, energy.potential);
  append_value(out, energy.total);
  out.push_back('\n');
}

void check_rows(const std::string& option, long rows, const std::string& why) {
  if (rows > InstrumentCsv::max_rows) {
    throw InputError(option + ": " + why + " make " + std::to_string(rows) +
                     " rows, more than the " + std::to_string(InstrumentCsv::max_rows) +
                     " a file may hold; ask for fewer --frames");
  }
}

}  // namespace

InstrumentCsv::InstrumentCsv(std::string convergence_path, std::string energy_path, long frames,
                             int iterations)
    : convergence_path_(std::move(convergence_path)), energy_path_(std::move(energy_path)) {
  if (!convergence_path_.empty()) {
    check_output_path("--convergence-csv", convergence_path_);
    // At most 10⁷ frames (--frames) of 5001 iterates: far inside a long.
    check_rows(
        "--convergence-csv", frames * (iterations + 1L),
        std::to_string(frames) + " frames of " + std::to_string(iterations + 1) + " iterates");
    convergence_ = convergence_csv_header;
  }
  if (!energy_path_.empty()) {
    check_output_path("--energy-csv", energy_path_);
    check_rows("--energy-csv", frames + 1, std::to_string(frames) + " frames");
    energy_ = "frame,time,kinetic,spring,gravity,potential,total\n";
  }
}

void InstrumentCsv::start(const Simulation& simulation) {
  if (!energy_path_.empty()) append_energy_row(energy_, 0, simulation);
}

void InstrumentCsv::record(long frame, const Simulation& simulation) {
  if (!convergence_path_.empty()) {
    const ConvergenceTrace& trace = simulation.last_convergence();
    if (convergence_rows_ + trace.iterations() + 1 <= max_rows) {
      convergence_rows_ += trace.iterations() + 1;
      append_convergence_rows(convergence_, frame, trace);
    }
  }
  if (!energy_path_.empty() && energy_rows_ < max_rows) {
    ++energy_rows_;
    append_energy_row(energy_, frame, simulation);
  }
}

void InstrumentCsv::write() const {
  if (!convergence_path_.empty()) write_output_file(convergence_path_, convergence_);
  if (!energy_path_.empty()) write_output_file(energy_path_, energy_);
}

}  // namespace wobble

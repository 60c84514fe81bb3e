#include "panel_stats.h"

#include <imgui.h>

#include <string>

namespace wobble {

namespace {

// Rows of label and value, aligned at `column` (in the default font's units).
void stat_row(const char* label, const char* format, double value, float column = 110.0f) {
  ImGui::TextUnformatted(label);
  ImGui::SameLine(column * ImGui::GetFontSize() / 13.0f);
  ImGui::Text(format, value);
}

}  // namespace

int panel_stats_lines(const PanelStats& stats) {
  return (stats.show_timings ? 4 : 3) + (stats.self_collision ? 1 : 0);
}

void draw_panel_stats(const PanelStats& stats, bool paused) {
  // Each line stays under about 44 characters, the panel's width in the default font.
  if (stats.show_timings) {
    // "\xc3\x97" is U+00D7, the multiplication sign: in the default font's Latin-1 range.
    // Whether the motion on screen is the simulation's own speed: it runs in slow motion when
    // the steps take longer than they simulate (or, without real time, when a frame does).
    if (paused) {
      ImGui::Text("fps %.1f (a frame %.1f ms), paused", stats.fps, stats.ui_frame_ms);
    } else if (stats.real_time_factor < 0.95f) {
      ImGui::Text("fps %.1f (a frame %.1f ms), \xc3\x97%.2f slow", stats.fps, stats.ui_frame_ms,
                  stats.real_time_factor);
    } else {
      ImGui::Text("fps %.1f (a frame %.1f ms), \xc3\x97%.2f", stats.fps, stats.ui_frame_ms,
                  stats.real_time_factor);
    }
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip(
          "Frames drawn per second and the UI's own time for one, steps apart;\n"
          "\xc3\x97: simulated seconds per second (under 1: slow motion)");
    }
    // With the timings: the thread count depends on the machine, and headless images must not.
    ImGui::Text("step %.2f ms, %.0f steps/s, %d thread%s", stats.step_ms, stats.steps_per_second,
                stats.threads, stats.threads == 1 ? "" : "s");
  } else {
    ImGui::TextDisabled("timings hidden (headless)");
  }
  if (stats.has_colliders) {
    ImGui::Text("simulated %.2f s, %d pins, %d contacts", stats.simulated_seconds, stats.pins,
                stats.contacts);
  } else {
    ImGui::Text("simulated %.2f s, %d pins", stats.simulated_seconds, stats.pins);
  }
  if (stats.solver.empty()) {
    ImGui::Text("%d vertices, %d springs", stats.vertices, stats.springs);
  } else {
    ImGui::Text("%d vertices, %d springs, %s", stats.vertices, stats.springs, stats.solver.c_str());
  }
  if (stats.self_collision) ImGui::Text("self contacts %d", stats.self_contacts);
}

void draw_panel_timings(const PanelStats& stats) {
  if (!stats.show_timings) return;
  stat_row("step", "%.2f ms", stats.step_ms);
  stat_row("  local", "%.2f ms", stats.local_ms);
  stat_row("  global", "%.2f ms", stats.global_ms);
  if (stats.forces_ms > 0.0f) stat_row("  wind", "%.2f ms", stats.forces_ms);
  if (stats.instruments_ms > 0.0f) stat_row("  plots", "%.2f ms", stats.instruments_ms);
  // The terms' own figures, each term's under its name; the names are longer than the rows
  // above, so their values sit further right.
  const std::string* term = nullptr;
  for (const PanelStats::TermFigure& figure : stats.term_figures) {
    if (!term || *term != figure.term) {
      term = &figure.term;
      ImGui::Text("  %s", figure.term.c_str());
    }
    const std::string label = "    " + figure.name;
    if (figure.unit.empty()) {
      stat_row(label.c_str(), "%.0f", figure.value, 150.0f);
    } else {
      stat_row(label.c_str(), ("%.2f " + figure.unit).c_str(), figure.value, 150.0f);
    }
  }
  stat_row("steps", "%.0f /s", stats.steps_per_second);
  stat_row("threads", "%.0f", stats.threads);
}

}  // namespace wobble

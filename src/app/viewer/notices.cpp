#include "app/viewer/notices.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>

namespace wobble {

void Notices::post(std::string text, double now) {
  notices_.push_back(Notice{std::move(text), now});
  // Older notices than the box shows are gone for good (the panel's notes keep them).
  if (notices_.size() > most_shown) notices_.erase(notices_.begin());
}

std::vector<std::string> Notices::shown(double now) const {
  std::vector<std::string> texts;
  for (const Notice& notice : notices_) {
    if (now - notice.posted < shown_seconds && now >= notice.posted) texts.push_back(notice.text);
  }
  return texts;
}

void Notices::draw(double now, float left, float right, float ui_scale, float top) const {
  const std::vector<std::string> texts = shown(now);
  if (texts.empty()) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float margin = 12.0f * ui_scale;
  const float width =
      std::max(200.0f * ui_scale, std::min(right, display.x) - left - 2.0f * margin);
  ImGui::SetNextWindowPos(ImVec2(left + margin, top + margin), ImGuiCond_Always);
  ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(width, display.y * 0.5f));
  ImGui::SetNextWindowBgAlpha(0.85f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav |
                                 ImGuiWindowFlags_NoInputs;
  if (ImGui::Begin("##notices", nullptr, flags)) {
    ImGui::PushTextWrapPos(width - margin);
    for (const std::string& text : texts) {
      const bool failed = text.find("failed") != std::string::npos;
      if (failed) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.55f, 0.45f, 1.0f));
      ImGui::TextUnformatted(text.c_str());
      if (failed) ImGui::PopStyleColor();
    }
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
}

double notice_clock() {
  static const auto start = std::chrono::steady_clock::now();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace wobble

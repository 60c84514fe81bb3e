#include "app/web/page_arguments.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "app/cli/scene_catalog.h"

namespace wobble {

namespace {

std::string decode(const std::string& text) {
  std::string decoded;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '+') {
      decoded += ' ';
    } else if (text[i] == '%' && i + 2 < text.size() && std::isxdigit(text[i + 1]) &&
               std::isxdigit(text[i + 2])) {
      decoded += static_cast<char>(std::strtol(text.substr(i + 1, 2).c_str(), nullptr, 16));
      i += 2;
    } else {
      decoded += text[i];
    }
  }
  return decoded;
}

}  // namespace

std::vector<std::string> page_arguments(const std::string& query,
                                        const std::vector<std::string>& catalog) {
  std::vector<std::string> arguments{"wobble"};
  std::string scene;
  std::vector<std::string> options;
  std::size_t start = !query.empty() && query[0] == '?' ? 1 : 0;
  while (start < query.size()) {
    std::size_t end = query.find('&', start);
    if (end == std::string::npos) end = query.size();
    const std::string pair = query.substr(start, end - start);
    start = end + 1;
    const std::size_t equals = pair.find('=');
    const std::string key = decode(pair.substr(0, equals));
    const std::string value = equals == std::string::npos ? "" : decode(pair.substr(equals + 1));
    if (key == "scene" && !value.empty()) {
      scene = value;
      for (const std::string& source : catalog) {
        if (scene_label(source) == value) {
          scene = source;
          break;
        }
      }
    } else if ((key == "k" || key == "dt" || key == "iterations" || key == "frames") &&
               !value.empty()) {
      options.push_back("--" + key);
      options.push_back(value);
    } else if (key == "plots") {
      options.push_back("--plots");
    }
  }
  // "--" first: a scene named like an option is still a scene.
  if (!scene.empty()) {
    arguments.push_back("--");
    arguments.push_back(scene);
  }
  arguments.insert(arguments.begin() + 1, options.begin(), options.end());
  return arguments;
}

double page_wheel_notches(double delta_y, unsigned long delta_mode) {
  if (!std::isfinite(delta_y)) return 0.0;
  const double per_notch = delta_mode == 0 ? 100.0 : delta_mode == 1 ? 3.0 : 1.0;
  // A burst of many at once (a page, a flung wheel) turns at most a few notches.
  return std::clamp(-delta_y / per_notch, -5.0, 5.0);
}

bool page_wants_bench(const std::string& query) {
  std::size_t start = !query.empty() && query[0] == '?' ? 1 : 0;
  while (start < query.size()) {
    std::size_t end = query.find('&', start);
    if (end == std::string::npos) end = query.size();
    const std::string pair = query.substr(start, end - start);
    if (decode(pair.substr(0, pair.find('='))) == "bench") return true;
    start = end + 1;
  }
  return false;
}

}  // namespace wobble

#include "app/web/page_arguments.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "app/cli/command_line.h"
#include "app/cli/scene_catalog.h"
#include "sim/input_error.h"

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

PageRequest read_page_address(const std::string& query, const std::vector<std::string>& catalog) {
  PageRequest request;
  std::string scene;
  std::vector<std::string> options;
  const auto refuse = [&](const std::string& key, const std::string& why) {
    request.refusals.push_back("address: " + key + ": " + why);
  };
  std::size_t start = !query.empty() && query[0] == '?' ? 1 : 0;
  while (start < query.size()) {
    std::size_t end = query.find('&', start);
    if (end == std::string::npos) end = query.size();
    const std::string pair = query.substr(start, end - start);
    start = end + 1;
    if (pair.empty()) continue;
    const std::size_t equals = pair.find('=');
    const std::string key = decode(pair.substr(0, equals));
    const std::string value = equals == std::string::npos ? "" : decode(pair.substr(equals + 1));
    if (key == "scene") {
      if (value.empty()) continue;
      std::string found;
      for (const std::string& source : catalog) {
        if (scene_label(source) == value || source == value) found = source;
      }
      // A path (a dropped file's, a scene beside the site) is tried as it is.
      const bool path =
          value.find('/') != std::string::npos || value.find('.') != std::string::npos;
      if (!found.empty() || path) {
        scene = found.empty() ? value : found;
      } else {
        std::string names;
        for (const std::string& source : catalog)
          names += (names.empty() ? "" : ", ") + scene_label(source);
        refuse(key, "no scene '" + value + "' (the scenes: " + names + "); opening the default");
      }
    } else if (key == "k" || key == "dt" || key == "iterations" || key == "frames") {
      // Read as the command line reads it, alone: one bad value costs only itself.
      const std::string option = "--" + key;
      const char* const argv[] = {"wobble", option.c_str(), value.c_str()};
      std::ostringstream ignored;
      try {
        parse_command_line(3, argv, ignored);
        options.push_back(option);
        options.push_back(value);
      } catch (const InputError& error) {
        std::string why = error.what();
        if (why.rfind(option + ": ", 0) == 0) why = why.substr(option.size() + 2);
        refuse(key, why);
      }
    } else if (key == "plots") {
      options.push_back("--plots");
    } else if (key != "bench") {
      refuse(key,
             "not a key of the address (it takes scene, k, dt, iterations, frames, plots "
             "and bench)");
    }
  }
  request.arguments = {"wobble"};
  request.arguments.insert(request.arguments.end(), options.begin(), options.end());
  // "--" first: a scene named like an option is still a scene.
  if (!scene.empty()) {
    request.arguments.push_back("--");
    request.arguments.push_back(scene);
  }
  return request;
}

std::vector<std::string> page_arguments(const std::string& query,
                                        const std::vector<std::string>& catalog) {
  return read_page_address(query, catalog).arguments;
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

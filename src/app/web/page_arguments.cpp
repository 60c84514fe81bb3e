#include "app/web/page_arguments.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include "app/cli/command_line.h"
#include "app/cli/scene_catalog.h"
#include "sim/input_error.h"
#include "sim/settings/setting_registry.h"

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

// The command line's options an address may give: every setting declared for it
// (SettingPlace::in_address) and the view, never an option that writes files or starts a
// process.
const std::vector<std::string> address_view_options = {"frames", "camera-yaw", "camera-pitch",
                                                       "camera-zoom", "color-by"};
const std::vector<std::string> address_view_switches = {"plots", "wireframe", "springs", "points"};

// The setting of that name the address may give, or null.
const SettingSpec* address_setting(const std::string& key) {
  const SettingSpec* spec = find_setting(key);
  return spec && spec->name == key && (spec->places & in_address) ? spec : nullptr;
}

bool is_address_setting(const std::string& key) {
  const SettingSpec* spec = address_setting(key);
  return (spec && spec->type != SettingType::toggle) ||
         std::find(address_view_options.begin(), address_view_options.end(), key) !=
             address_view_options.end();
}

bool is_address_switch(const std::string& key) {
  const SettingSpec* spec = address_setting(key);
  return (spec && spec->type == SettingType::toggle) ||
         std::find(address_view_switches.begin(), address_view_switches.end(), key) !=
             address_view_switches.end();
}

std::string address_keys() {
  std::string keys = "scene";
  for (const SettingSpec& spec : all_settings()) {
    if ((spec.places & in_address) && spec.type != SettingType::toggle) keys += ", " + spec.name;
  }
  for (const std::string& key : address_view_options)
    keys += ", " + key;
  for (const SettingSpec& spec : all_settings()) {
    if ((spec.places & in_address) && spec.type == SettingType::toggle) keys += ", " + spec.name;
  }
  for (const std::string& key : address_view_switches)
    keys += ", " + key;
  return keys + " and bench";
}

// The shortest decimal that reads back as `value` exactly.
std::string exact_number(double value) {
  for (int digits = 6; digits < 17; ++digits) {
    std::ostringstream text;
    text << std::setprecision(digits) << value;
    if (std::stod(text.str()) == value) return text.str();
  }
  std::ostringstream text;
  text << std::setprecision(17) << value;
  return text.str();
}

// An angle to a hundredth of a degree, without trailing zeros: "47.35", "-20", "0".
std::string hundredths(double value) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(2) << value;
  std::string shown = text.str();
  while (shown.back() == '0')
    shown.pop_back();
  if (shown.back() == '.') shown.pop_back();
  return shown == "-0" ? "0" : shown;
}

std::string encode(const std::string& text) {
  static const char hex[] = "0123456789ABCDEF";
  std::string encoded;
  for (const unsigned char c : text) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~' || c == '/') {
      encoded += static_cast<char>(c);
    } else {
      encoded += '%';
      encoded += hex[c >> 4];
      encoded += hex[c & 15];
    }
  }
  return encoded;
}

}  // namespace

std::string page_link_query(const std::string& scene_label, const SimulationParams& opened,
                            const SimulationParams& current, const PageView& view) {
  std::string query = "?scene=" + encode(scene_label);
  const auto number = [&](const char* key, double was, double is) {
    if (is != was) query += std::string("&") + key + "=" + exact_number(is);
  };
  const auto on = [&](const char* key, bool was, bool is) {
    if (is && !was) query += std::string("&") + key;
  };
  // Every setting the address takes, where it differs from the scene's own.
  for (const SettingSpec& spec : all_settings()) {
    if (!(spec.places & in_address)) continue;
    const SettingValue was = spec.get(opened), is = spec.get(current);
    if (spec.type == SettingType::toggle) {
      on(spec.name.c_str(), std::get<bool>(was), std::get<bool>(is));
    } else if (spec.type == SettingType::choice) {
      if (is != was) query += "&" + spec.name + "=" + encode(std::get<std::string>(is));
    } else if (spec.type != SettingType::vector) {
      number(spec.name.c_str(), setting_number(was), setting_number(is));
    }
  }
  // The view: the colour, the switches on, the camera.
  if (view.color_by != ColorQuantity::material) {
    query += std::string("&color-by=") + color_quantity_name(view.color_by);
  }
  on("wireframe", false, view.wireframe);
  on("springs", view.faceless, view.springs);
  on("points", view.faceless, view.points);
  on("plots", false, view.plots);
  const std::string yaw = hundredths(view.yaw_degrees), pitch = hundredths(view.pitch_degrees);
  if (yaw != hundredths(view.scene_yaw_degrees)) query += "&camera-yaw=" + yaw;
  if (pitch != hundredths(view.scene_pitch_degrees)) query += "&camera-pitch=" + pitch;
  std::ostringstream zoom;
  zoom << std::setprecision(4) << view.zoom;
  if (std::isfinite(view.zoom) && view.zoom > 0.0 && zoom.str() != "1")
    query += "&camera-zoom=" + zoom.str();
  return query;
}

std::string page_link_keys(const std::string& query) {
  std::string keys;
  std::size_t start = !query.empty() && query[0] == '?' ? 1 : 0;
  while (start < query.size()) {
    std::size_t end = query.find('&', start);
    if (end == std::string::npos) end = query.size();
    const std::string pair = query.substr(start, end - start);
    if (!pair.empty()) keys += (keys.empty() ? "" : ", ") + pair.substr(0, pair.find('='));
    start = end + 1;
  }
  return keys;
}

std::vector<std::string> page_link_losses(const SimulationParams& opened,
                                          const SimulationParams& current, const PageView& view) {
  std::vector<std::string> lost;
  if (view.faceless && !view.springs) lost.push_back("the springs off");
  if (view.faceless && !view.points) lost.push_back("the points off");
  if (view.panned) lost.push_back("the camera's pan");
  // An address only turns a switch on; a setting it has no key for is lost when changed.
  for (const SettingSpec& spec : all_settings()) {
    const SettingValue was = spec.get(opened), is = spec.get(current);
    if (is == was) continue;
    if (!(spec.places & in_address)) {
      lost.push_back(spec.label);
    } else if (spec.type == SettingType::toggle && !std::get<bool>(is)) {
      lost.push_back(spec.label + " off");
    }
  }
  return lost;
}

PageRequest read_page_address(const std::string& query, const std::vector<std::string>& catalog) {
  PageRequest request;
  std::string scene;
  // The options the address gives, in its order, each key once: a key given again replaces its
  // value (the command line refused the pair, and the page opened the default scene instead).
  struct Given {
    std::string key;
    std::vector<std::string> words;  // "--k", "2000"; a switch's word alone
  };
  std::vector<Given> given;
  const auto refuse = [&](const std::string& key, const std::string& why) {
    request.refusals.push_back("address: " + key + ": " + why);
  };
  const auto take = [&](const std::string& key, std::vector<std::string> words) {
    for (Given& earlier : given) {
      if (earlier.key != key) continue;
      refuse(key, "given twice; the last is used");
      earlier.words = std::move(words);
      return;
    }
    given.push_back(Given{key, std::move(words)});
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
        // By its picker label ("banner"), its source, or its path's end without the extension
        // ("course/banner").
        const std::string stem = std::filesystem::path(source).replace_extension().string();
        const bool ends = stem.size() > value.size() &&
                          stem.compare(stem.size() - value.size(), value.size(), value) == 0 &&
                          stem[stem.size() - value.size() - 1] == '/';
        if (scene_label(source) == value || source == value || ends) found = source;
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
    } else if (is_address_setting(key)) {
      // Read as the command line reads it, alone: one bad value costs only itself.
      const std::string option = "--" + key;
      const char* const argv[] = {"wobble", option.c_str(), value.c_str()};
      std::ostringstream ignored;
      try {
        parse_command_line(3, argv, ignored);
        take(key, {option, value});
      } catch (const InputError& error) {
        std::string why = error.what();
        if (why.rfind(option + ": ", 0) == 0) why = why.substr(option.size() + 2);
        refuse(key, why);
      }
    } else if (is_address_switch(key)) {
      // "plots", "plots=1" or "plots=on" turns it on; "plots=0" leaves it as the scene has it.
      if (value.empty() || value == "1" || value == "on" || value == "true") {
        take(key, {"--" + key});
      } else if (value != "0" && value != "off" && value != "false") {
        refuse(key, "expected no value, 1 or 0, got '" + value + "'");
      }
    } else if (key != "bench") {
      refuse(key, "not a key of the address (it takes " + address_keys() + ")");
    }
  }
  request.arguments = {"wobble"};
  for (const Given& option : given) {
    // A course scene keeps the reference's method: what the command line refuses for one
    // (self-collision, Chebyshev, ...) is left out and said, instead of costing the whole address.
    if (is_course_scene_source(scene)) {
      std::vector<const char*> argv = {"wobble"};
      for (const std::string& word : option.words)
        argv.push_back(word.c_str());
      std::ostringstream ignored;
      try {
        SimulationParams course;
        course.gravity_model = GravityModel::force_per_vertex;
        apply_scene_overrides(
            *parse_command_line(static_cast<int>(argv.size()), argv.data(), ignored), course);
      } catch (const InputError& error) {
        std::string why = error.what();
        const std::string& word = option.words.front();
        if (why.rfind(word + ": ", 0) == 0) why = why.substr(word.size() + 2);
        refuse(option.key, why + "; left out");
        continue;
      }
    }
    request.arguments.insert(request.arguments.end(), option.words.begin(), option.words.end());
  }
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

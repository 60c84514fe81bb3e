#ifndef WOBBLE_IO_JSON_FIELDS_H
#define WOBBLE_IO_JSON_FIELDS_H

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "sim/value_limits.h"

namespace wobble {

// Typed access to the keys of one JSON object of a scene file, with errors that name the file
// and the key's full path ("scene.json: material.k: expected a positive number, got -3"). Each
// object says which keys it takes (allow_only), and any other key is refused.
class JsonFields {
 public:
  // `object` must outlive this. `path` is the key path of the object ("" at the top).
  JsonFields(const std::string& file, const nlohmann::json& object, std::string path = "");
  // A temporary object would be gone before the first key is read.
  JsonFields(const std::string& file, nlohmann::json&& object, std::string path = "") = delete;

  bool has(const std::string& key) const;
  // The child object at `key` (InputError if it is not an object).
  JsonFields object(const std::string& key);
  const nlohmann::json& raw(const std::string& key);

  std::optional<double> positive(const std::string& key);
  std::optional<double> number(const std::string& key);
  // A number within `range` (see sim/value_limits.h).
  std::optional<double> number_in(const std::string& key, const ValueRange& range);
  std::optional<int> whole(const std::string& key, int low, int high);
  std::optional<bool> flag(const std::string& key);
  std::optional<std::string> text(const std::string& key);
  // Three finite numbers, [x, y, z].
  std::optional<Eigen::Vector3d> vector3(const std::string& key);
  // Three numbers [x, y, z], each within `range`.
  std::optional<Eigen::Vector3d> vector3_in(const std::string& key, const ValueRange& range);
  // Three numbers in [0, 1].
  std::optional<Eigen::Vector3d> color(const std::string& key);

  // Refuse the first key of this object that is not in `keys`, before any value is read:
  // InputError "FILE: PATH.KEY: unknown key, WHAT takes KEYS" (WHAT: "a cloth mesh").
  void allow_only(const std::vector<std::string>& keys, const std::string& what) const;

  // "FILE: PATH.KEY: MESSAGE", for errors found by the caller.
  std::string where(const std::string& key) const;
  [[noreturn]] void fail(const std::string& key, const std::string& expected) const;

 private:
  std::string file_;
  const nlohmann::json& object_;
  std::string path_;
};

// `value` as a message shows it: its JSON, cut to about `max_chars` characters ("[1,2,3,...").
// Only what is shown is written out, so a list of a million items costs nothing.
std::string json_preview(const nlohmann::json& value, std::size_t max_chars = 40);

// The value of a JSON number that is a whole number from `low` to `high`, however the file
// spells it (7, 7.0, 7e0, 0.7e1, 700e-2), or nothing: not a number, a fraction, or out of range.
// Every whole-number field of a scene, in either format, is read through this.
std::optional<long long> whole_number(const nlohmann::json& value, long long low, long long high);

}  // namespace wobble

#endif

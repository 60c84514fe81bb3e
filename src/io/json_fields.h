#ifndef WOBBLE_IO_JSON_FIELDS_H
#define WOBBLE_IO_JSON_FIELDS_H

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "sim/value_limits.h"

namespace wobble {

// Typed access to the keys of one JSON object of a scene file, with errors that name the file
// and the key's full path ("scene.json: material.k: expected a positive number, got -3"), and a
// record of which keys were read, so the unread ones can be reported as unknown.
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

  // "FILE: PATH.KEY: MESSAGE", for errors found by the caller.
  std::string where(const std::string& key) const;
  [[noreturn]] void fail(const std::string& key, const std::string& expected) const;

  // Keys present but never read, as full paths, for a warning.
  std::vector<std::string> unread() const;

 private:
  std::string file_;
  const nlohmann::json& object_;
  std::string path_;
  std::set<std::string> read_;
};

}  // namespace wobble

#endif

#ifndef WOBBLE_IO_READ_JSON_FILE_H
#define WOBBLE_IO_READ_JSON_FILE_H

#include <nlohmann/json.hpp>
#include <string>

namespace wobble {

// Parse a JSON file. Throws InputError on one line: "PATH: no such file ..." or
// "PATH: line L: malformed JSON: <what nlohmann expected>".
nlohmann::json read_json_file(const std::string& path);

}  // namespace wobble

#endif
